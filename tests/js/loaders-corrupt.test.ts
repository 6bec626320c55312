// Corrupted GIS files (tests/fixtures-gis/corrupt, made by its make.mjs, each
// named after what it reproduces) are refused by hodt/loaders with one
// InputError of one printable line naming the field and the value, and by the
// npm CLI with exit 2 and exactly that line; reading LAZ files again and again
// leaves nothing behind. A short run of the loader fuzzer ends the file.
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { InputError } from '../../web/src/errors.js';
import { readLAS, readPointFile } from '../../web/src/loaders/index.js';
import { Directory } from '../../web/src/loaders/tiff/ifd.js';
import { describeRaster } from '../../web/src/loaders/tiff/raster.js';
import { FILES } from '../fixtures-gis/corrupt/make.mjs';
import { describe as describeFuzz, fuzzLoaders } from '../fuzz/loaders/fuzz.mjs';

const root = new URL('../../', import.meta.url).pathname;
const corrupt = (name: string) => `${root}tests/fixtures-gis/corrupt/${name}`;

const EXPECTED: Record<string, RegExp> = {
  'lzw-byte-zeroed.tif': /^GeoTIFF: strip 0: its LZW data cannot be decoded \(LZW code \d+ is not in the table/,
  'height-16777221.tif': /^GeoTIFF: the raster is 40 x 16777221 cells, more than 50000000/,
  'strip-too-short-for-its-rows.tif': /^TIFF: strip 0: 815 bytes of LZW data cannot hold its 40 x 100000 cells/,
  'no-strip-offsets.tif': /^TIFF: tag StripOffsets is missing/,
  'strip-byte-count-0.tif': /^TIFF: strip 0 has StripByteCounts 0: its data are missing$/,
  'raw-flagged-zstd.tif': /^GeoTIFF: strip 0: its data are flagged ZSTD but do not start a ZSTD frame$/,
  'raw-flagged-lzw.tif': /^GeoTIFF: strip 0: its LZW data cannot be decoded/,
  'pixel-scale-nan.tif': /^GeoTIFF: ModelPixelScale \(33550\) is \(NaN, 2\.5, 0\), expected finite non-zero cell sizes$/,
  'pixel-scale-1e308.tif': /^GeoTIFF: the georeferencing puts the raster's corner \(column 40, row 0\) at an infinite coordinate$/,
  'ifd-offset-past-end.tif': /^TIFF: the first IFD's offset is 1048576, outside the file's 1205 bytes$/,
  'record-length-0.las': /^LAS: point record length 0, expected at least 20 for point format 0$/,
  'count-100000000.las': /^LAS: the header promises 100000000 points of 20 bytes from byte 1207; the file has 22507 bytes, room for 1065$/,
  'count-100000000.laz': /^LAZ: the header promises 100000000 points; the chunk table's 1 chunks of 50000 points hold 1 to 50000$/,
  'point-offset-in-header.las': /^LAS: variable length record 0 of 4 starts at byte 227, past the point data offset \(100\)$/,
  'record-length-12.las': /^LAS: point record length 12, expected at least 20 for point format 0$/,
  'format-6-on-20-byte-records.las': /^LAS: point data record format 6 in a LAS 1\.2 file/,
  'laz-chunk-overwritten.laz': /^LAZ: the compressed points are corrupt: LASzip failed at point \d+ of 1065$/,
};

describe('corrupted GIS files', () => {
  it('every fixture is what make.mjs makes, and has an expected message', () => {
    expect(Object.keys(FILES).sort()).toEqual(Object.keys(EXPECTED).sort());
    for (const [name, make] of Object.entries(FILES)) expect(new Uint8Array(readFileSync(corrupt(name)))).toEqual(make());
  });

  for (const [name, expected] of Object.entries(EXPECTED)) {
    it(`${name}: one InputError, one line`, async () => {
      const started = Date.now();
      const error = await readPointFile(new Uint8Array(readFileSync(corrupt(name)))).then(
        () => null,
        (e: unknown) => e,
      );
      expect(error).toBeInstanceOf(InputError);
      expect((error as Error).message).toMatch(expected);
      expect((error as Error).message).toMatch(/^[\x20-\x7e]+$/);
      expect(Date.now() - started).toBeLessThan(5000);
    });
  }

  it('the npm CLI: exit 2, the file and the same message on one line, no notes', () => {
    for (const name of ['lzw-byte-zeroed.tif', 'raw-flagged-zstd.tif', 'record-length-0.las', 'laz-chunk-overwritten.laz']) {
      const r = spawnSync('node', [`${root}dist/cli.js`, 'solve', corrupt(name), '--objective', 'min-local-minima'], { encoding: 'utf8' });
      expect(r.status).toBe(2);
      expect(r.stdout).toBe('');
      const lines = r.stderr.split('\n').filter(Boolean);
      expect(lines).toHaveLength(1);
      expect(lines[0]).toContain(corrupt(name));
      expect(lines[0]!.slice(lines[0]!.indexOf(`${name}: `) + name.length + 2)).toMatch(EXPECTED[name]!);
    }
  });

  it('a GIS point the core refuses is named by its cell, not by a line of text', () => {
    const b = new Uint8Array(readFileSync(`${root}tests/fixtures-gis/dem-utm-float64-pixel-is-point.tif`));
    // (the raw float64 samples of the first strip, 8 bytes a cell: row 0, column 10 made huge)
    const strip = describeRaster(new Directory(b), 0).chunks[0]!.offset;
    new DataView(b.buffer).setFloat64(strip + 8 * 10, 1e300, true);
    const file = join(mkdtempSync(join(tmpdir(), 'hodt-corrupt-')), 'huge-height.tif');
    writeFileSync(file, b);
    const r = spawnSync('node', [`${root}dist/cli.js`, 'stats', file], { encoding: 'utf8' });
    expect(r.status).toBe(2);
    expect(r.stderr).toMatch(/^hodt: .*huge-height\.tif: point \d+ \(row 0, column 10\): z is 1e\+300, outside the supported range/);
    expect(r.stderr.split('\n').filter(Boolean)).toHaveLength(1);
  });
});

describe('LAZ reads leave nothing behind', () => {
  it('300 reads of a LAZ file: no process listener added, memory flat', async () => {
    const laz = new Uint8Array(readFileSync(`${root}tests/fixtures-gis/lidar-point10.laz`));
    const listeners = () => ['uncaughtException', 'unhandledRejection', 'exit'].map((e) => process.listenerCount(e));
    await readLAS(laz); // (the laz-perf module is made once, on first use)
    const before = listeners();
    const rss = process.memoryUsage().rss;
    for (let i = 0; i < 300; ++i) await readLAS(laz);
    expect(listeners()).toEqual(before);
    expect(process.memoryUsage().rss - rss).toBeLessThan(100 * 2 ** 20);
    // A corrupted file in between drops the module; the next read makes a new one.
    await expect(readLAS(new Uint8Array(readFileSync(corrupt('laz-chunk-overwritten.laz'))))).rejects.toThrow(InputError);
    expect((await readLAS(laz, { classes: 'all' })).xyz.length).toBe(3 * 1065);
    expect(listeners()).toEqual(before);
  });
});

describe('the loader fuzzer, briefly', () => {
  it('2,000 mutated files: no crash, hang, untyped or multi-line error, no silent read of missing data', async () => {
    const stats = await fuzzLoaders({ files: 2000, first: 1_000_000, cliFiles: 4, workers: 2 });
    console.log(describeFuzz(stats));
    expect(stats.findings).toEqual([]);
    expect(stats.runs).toBe(2000);
  }, 120_000);
});
