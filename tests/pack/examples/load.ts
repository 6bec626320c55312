// docs/api.md "Loading": hodt.wasm from somewhere else than next to the JS.
import { loadHodt } from 'hodt';

const hodt = await loadHodt({ wasmUrl: new URL('/assets/hodt.wasm', 'https://example.com') });
console.log(hodt.objectives.map((o) => o.id));
