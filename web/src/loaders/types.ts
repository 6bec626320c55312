/** Points read from a GIS file. */
export interface PointCloud {
  /** x, y, z per point, in the file's own units (no reprojection). */
  xyz: Float64Array;
  /** The coordinate reference system when the file names one by code, e.g. "EPSG:32633". */
  crs?: string;
  /** What the loader skipped or assumed, one line each. */
  warnings: string[];
  /** Rasters with cells without data: the default domain, 3 cells (pass it as
   * `hodt.terrain(xyz, { maxEdge })`), so that triangles bridging the gaps are not
   * measured. Absent when every cell has data, and for point clouds. */
  maxEdge?: number;
  /** Where point i was read from, in words ('row 12, column 3' of a raster,
   * 'point record 128' of a LAS file), for messages about that point. */
  origin(i: number): string;
}
