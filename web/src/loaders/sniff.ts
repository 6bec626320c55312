// Which GIS format a file's first bytes announce: no dependency, so that the CLI
// asks before it loads the readers (geotiff's modules take about 50 ms to load).
export type BinaryFormat = 'geotiff' | 'las';

/** The GIS format a file's first bytes announce, or null (text, or unknown). */
export function sniffFormat(bytes: Uint8Array): BinaryFormat | null {
  const [a, b, c, d] = [bytes[0], bytes[1], bytes[2], bytes[3]];
  if ((a === 0x49 && b === 0x49 && (c === 42 || c === 43) && d === 0) || (a === 0x4d && b === 0x4d && c === 0 && (d === 42 || d === 43)))
    return 'geotiff';
  if (a === 0x4c && b === 0x41 && c === 0x53 && d === 0x46) return 'las'; // "LASF", also LAZ
  return null;
}
