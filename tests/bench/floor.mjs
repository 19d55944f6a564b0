// The loop's speed against the floor: ../shared/bench/rustfloor, a dependency-free program with
// the plant's RK4 and the 5-state Euler EKF in plain f64, nothing recorded, no controller. The
// bench builds it, then times whole processes by their CPU time (user + system), each path side
// by side with the floor in every repetition, over the same 400,000 steps (20 s of `ramp`):
//   floor     rustfloor 400000 1
//   loop      imlab run --every 100000000 'v=1&preset=ramp&duration=20'   (nothing kept)
//   metrics   imlab metrics 'v=1&preset=ramp&duration=20'                 (the run and its figures)
//   page      page_run 'v=1&preset=ramp&duration=20'                      (the run as the page runs it:
//             traced, the overview of its eight plots, then the view, stability and report the
//             worker sends; crate/benches/page_run.rs)
// and prints each path's speed as a fraction of the floor's (floor CPU / path CPU), the median
// (min–max) of BENCH_REPS repetitions (default 7).
import { execFileSync } from 'node:child_process';
import { cpu } from './cpu.mjs';
import { benchExecutable } from './cargo.mjs';

const root = new URL('../../', import.meta.url).pathname;
const floorDir = new URL('../../../shared/bench/rustfloor/', import.meta.url).pathname;
const reps = Number(process.env.BENCH_REPS ?? 7);
const run = 'v=1&preset=ramp&duration=20';

execFileSync(
  'cargo',
  ['build', '--release', '-q', '--manifest-path', `${floorDir}Cargo.toml`, '--target-dir', `${root}target/floor`],
  { stdio: 'inherit' },
);
const floor = `${root}target/floor/release/rustfloor`;
const imlab = `${root}target/release/imlab`;

const paths = {
  loop: [imlab, 'run', '--every', '100000000', run],
  metrics: [imlab, 'metrics', run],
  page: [benchExecutable('page_run'), run],
};
const ratios = Object.fromEntries(Object.keys(paths).map((k) => [k, []]));
for (let r = 0; r < reps; r++) {
  for (const [name, argv] of Object.entries(paths)) {
    const f = cpu([floor, '400000', '1']);
    ratios[name].push(f / cpu(argv));
  }
}
const median = (v) => [...v].sort((a, b) => a - b)[Math.floor(v.length / 2)];
console.log(`speed against the floor (floor CPU / path CPU, 400,000 steps, ${reps} repetitions; median (min–max)):`);
for (const [name, v] of Object.entries(ratios)) {
  console.log(
    `  ${name.padEnd(8)} ${median(v).toFixed(2)} (${Math.min(...v).toFixed(2)}–${Math.max(...v).toFixed(2)})`,
  );
}
