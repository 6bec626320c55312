/** Points read from a GIS file. */
export interface PointCloud {
  /** x, y, z per point, in the file's own units (no reprojection). */
  xyz: Float64Array;
  /** The coordinate reference system when the file names one by code, e.g. "EPSG:32633". */
  crs?: string;
  /** What the loader skipped or assumed, one line each. */
  warnings: string[];
}
