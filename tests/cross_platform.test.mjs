// Native and wasm32 give bit-identical runs: the CSV of each WASM build (the page's run module,
// dist/pkg-run/, and the module with the tools, dist/pkg/) equals `imlab run` byte for byte.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import * as full from '../dist/pkg/imlab.js';
import * as run from '../dist/pkg-run/imlab.js';

const { presets } = full;
for (const [core, dir] of [
  [full, 'pkg'],
  [run, 'pkg-run'],
])
  core.initSync({ module: readFileSync(new URL(`../dist/${dir}/imlab_bg.wasm`, import.meta.url)) });
const cli = new URL('../target/release/imlab', import.meta.url).pathname;

function wasmCsv(Simulation, scenario) {
  const sim = new Simulation(scenario);
  while (!sim.finished) sim.step(50_000);
  // In chunks of rows, as the page exports it.
  const parts = [];
  for (let start = 0; start < sim.rows; start += 20_000) parts.push(sim.csv_chunk(start, 20_000));
  sim.free();
  return Buffer.concat(parts).toString();
}

/** A step's own law in a link. */
const law = (step, text) => `law.v${step}=${encodeURIComponent(text)}`;

const scenarios = [
  ...presets().map((p) => p.name),
  // Own laws with every function of the language (libm's, the same on every target).
  `v=1&preset=step&duration=0.05&${law(1, '-si1 + dwd + a3*wd + a2 - k1s1*z1 + 0.01*sin(z1)*exp(-abs(z1)) + 1e-3*atan2(x2, x3)')}&${law(
    3,
    '2*a8*(x4h^2 + x5h^2) - 2*a10*(xt2*x4h + xt3*x5h) + 2*(x4h*si4 + x5h*si5) - sat(k3*z3, 500) + 1e-6*tanh(sqrt(x4h^2 + x5h^2)) + 1e-9*cos(ln(1 + z3^2)) + 0*max(sign(z3), min(z3, 1))',
  )}`,
  'v=1&preset=step&ekf=rk4&seed=123456789&noise=0.01&substeps=3',
  'v=1&preset=ramp&plant.rr=5.5&load.torque=1&load.time=0.2&robust=1&h2=5&h4=5',
  'v=1&preset=sine200-1rad&duration=0.05&vlimit=circle&vdc=600&delay=1&delay.comp=1&ekf.load=1',
  'v=1&preset=ifoc-step&ifoc.ff=1&delay=1&vlimit=hex&pwm=1&substeps=2',
];

for (const s of scenarios) {
  test(`wasm CSV equals native CLI CSV: ${s}`, () => {
    const native = execFileSync(cli, ['run', s], { maxBuffer: 1 << 30 }).toString();
    assert.ok(native.split('\n').length > 100);
    assert.equal(wasmCsv(run.Simulation, s), native, 'the run module');
    assert.equal(wasmCsv(full.Simulation, s), native, 'the module with the tools');
  });
}
