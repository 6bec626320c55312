export {};

declare global {
  interface Window {
    /** Set once the first frame is drawn; read by tests/e2e. */
    __hodt?: { ready: boolean; points: number; quads: number; triangles: number };
  }
}
