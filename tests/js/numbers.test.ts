// Numbers read in wasm exactly as JavaScript reads them: Number() rounds every
// decimal correctly, so a CSV of random doubles written with 17 significant
// digits (numpy's savetxt('%.17g')), fewer, subnormal or huge must come back bit
// for bit through the library's reader (the core's fast_float in wasm).
import { beforeAll, describe, expect, it } from 'vitest';
import { type Hodt, loadHodt } from '../../web/src/index.js';

let hodt: Hodt;
beforeAll(async () => {
  hodt = await loadHodt();
});

// splitmix-like 32-bit LCG pairs: the same doubles on every run.
function randomBits(seed: number): () => bigint {
  let s = BigInt(seed);
  return () => {
    s = (s * 6364136223846793005n + 1442695040888963407n) & 0xffffffffffffffffn;
    return s;
  };
}

// A finite double with any exponent (subnormals included), as text.
function decimals(count: number, seed: number): string[] {
  const next = randomBits(seed);
  const view = new DataView(new ArrayBuffer(8));
  const out: string[] = [];
  while (out.length < count) {
    view.setBigUint64(0, next());
    const v = view.getFloat64(0);
    if (!Number.isFinite(v)) continue;
    const kind = out.length % 4;
    if (kind === 0) out.push(v.toPrecision(17));
    else if (kind === 1) out.push(v.toPrecision(1 + (out.length % 16)));
    else if (kind === 2) out.push(String(v));
    else out.push(`${(out.length % 7) - 3}${(Number(next() % 100000000000000000n) / 1e17).toFixed(17).slice(1)}e${Number(next() % 620n) - 320}`);
  }
  return out;
}

describe('numbers in wasm', () => {
  it('a 17-digit CSV of random doubles reads bit for bit as Number() reads it', () => {
    const tokens = decimals(60000, 56);
    const lines = ['x,y,z'];
    for (let i = 0; i < tokens.length; i += 3) lines.push(tokens.slice(i, i + 3).join(','));
    const read = hodt.readPoints(lines.join('\n') + '\n', 'numbers.csv');
    expect(read.points.length).toBe(tokens.length);
    const got = new BigUint64Array(read.points.buffer, read.points.byteOffset, read.points.length);
    const want = new BigUint64Array(Float64Array.from(tokens, Number).buffer);
    let wrong = -1;
    for (let i = 0; i < tokens.length && wrong < 0; ++i) if (got[i] !== want[i]) wrong = i;
    expect(wrong < 0 ? 'all equal' : `${tokens[wrong]}: ${read.points[wrong]}`).toBe('all equal');
  });

  it('edge cases: the smallest subnormal, halfway cases, the largest double, signs and exponents', () => {
    const tokens = ['4.9406564584124654e-324', '2.4703282292062328e-324', '2.2250738585072011e-308', '1.7976931348623157e308',
      '9007199254740993', '9007199254740993.0000000000000000000000000000001', '0.1000000000000000055511151231257827021181583404541015625',
      '+1E+03', '-0', '+.5', '5.', '1e-400'];
    const text = tokens.map((t, i) => `${i} ${i % 2} ${t}`).join('\n');
    const z = hodt.readPoints(text, 'edges.txt').points.filter((_, i) => i % 3 === 2);
    expect(Array.from(z)).toEqual(tokens.map(Number));
    expect(Object.is(z[8], -0)).toBe(true);
  });
});
