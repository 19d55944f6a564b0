// The same WASM build in Node: closed-loop steps per second, best of 40 one-second runs of `ramp`.
import { readFileSync } from 'node:fs';
import { initSync, Simulation } from '../../dist/pkg/imlab.js';

initSync({ module: readFileSync(new URL('../../dist/pkg/imlab_bg.wasm', import.meta.url)) });
let best = 0;
for (let r = 0; r < 40; r++) {
  const sim = new Simulation('v=1&preset=ramp&duration=1');
  const t = performance.now();
  while (!sim.finished) sim.step(5000);
  best = Math.max(best, sim.total / ((performance.now() - t) / 1000));
  sim.free();
}
console.log(`WASM closed loop in Node: ${(best / 1e6).toFixed(2)} M steps/s (${(best * 50e-6).toFixed(0)}× real time), best of 40 runs of 20 000 steps`);
