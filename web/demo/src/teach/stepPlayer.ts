// The Start / Prev / Play / Next stepping shared by the teaching views: a position
// from 0 to last(), advanced by a timer while playing.
export class StepPlayer {
  pos = 0;
  #timer = 0;
  #button: HTMLButtonElement | null = null;

  constructor(
    private readonly last: () => number,
    private readonly render: () => void,
    private readonly intervalMs: number,
  ) {}

  /** The Play / Pause button whose label follows the state. */
  attach(button: HTMLButtonElement): void {
    this.#button = button;
  }

  get playing(): boolean {
    return this.#timer !== 0;
  }

  go(p: number): void {
    this.pos = Math.max(0, Math.min(this.last(), p));
    if (this.pos === this.last()) this.stop();
    this.render();
  }

  start(): void {
    if (this.pos >= this.last()) this.pos = 0;
    if (this.#button) this.#button.textContent = '⏸ Pause';
    this.#timer = window.setInterval(() => this.go(this.pos + 1), this.intervalMs);
    this.render();
  }

  stop(): void {
    clearInterval(this.#timer);
    this.#timer = 0;
    if (this.#button) this.#button.textContent = '▶ Play';
  }

  toggle(): void {
    if (this.playing) this.stop();
    else this.start();
  }
}
