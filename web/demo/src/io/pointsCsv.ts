/** The points as CSV with a header. Numbers are written in JavaScript's shortest
 * round-trip form, so reading the file back gives the identical doubles. */
export function pointsToCsv(xyz: Float64Array): string {
  const lines = ['x,y,z'];
  for (let i = 0; i < xyz.length; i += 3) lines.push(`${xyz[i]},${xyz[i + 1]},${xyz[i + 2]}`);
  return `${lines.join('\n')}\n`;
}
