// One loader fuzzing worker: reads the mutated files of seeds FROM to TO (mutate.mjs)
// through hodt/loaders (dist/), telling its parent the seed before each file and
// every finding after it. A finding: an error that is not an InputError, a message
// that is not one printable line, a file that must be refused read without error,
// or points that are not finite triples.
//
//   node tests/fuzz/loaders/worker.mjs FROM TO
import { mutate } from './mutate.mjs';

const { readPointFile } = await import(new URL('../../../dist/loaders/index.js', import.meta.url).href);
const [from, to] = process.argv.slice(2).map(Number);
const send = (m) => process.send?.(m) ?? console.log(JSON.stringify(m));

function check(m, outcome) {
  if (outcome.error) {
    const e = outcome.error;
    if (!(e instanceof Error) || e.name !== 'InputError') return `untyped error ${e?.name}: ${String(e?.message ?? e).slice(0, 200)}`;
    if (!/^[\x20-\x7e]{1,300}$/.test(e.message)) return `message not one printable line: ${JSON.stringify(e.message.slice(0, 300))}`;
    return null;
  }
  const cloud = outcome.cloud;
  if (m.mustRefuse) return `read without error (${cloud ? cloud.xyz.length / 3 : 0} points) although ${m.what}`;
  if (!cloud) return null; // (not a GIS file any more: the CLI reads it as text)
  if (cloud.xyz.length === 0 || cloud.xyz.length % 3 !== 0) return `${cloud.xyz.length} coordinates`;
  for (const c of cloud.xyz) if (!Number.isFinite(c)) return `a coordinate is ${c}`;
  return null;
}

for (let seed = from; seed < to; ++seed) {
  const m = mutate(seed);
  send({ seed });
  const outcome = {};
  try {
    outcome.cloud = await readPointFile(m.bytes, { classes: seed & 1 ? 'all' : 'ground' });
  } catch (e) {
    outcome.error = e;
  }
  const finding = check(m, outcome);
  if (finding) send({ seed, finding, fixture: m.name, what: m.what });
}
send({ done: true });
