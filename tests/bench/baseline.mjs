// The paper's five-state path against the build before the six- and seven-state EKF options
// (commit f3ff4f2), side by side: options a run does not use must cost it nothing. The bench
// extracts that commit's tree (`git archive`, so it needs the repository's history), builds its
// `imlab`, and times whole processes by their CPU time (user + system), the two alternating in
// every repetition, over the same 400,000 steps (20 s of `ramp`, nothing kept):
//   imlab run --every 100000000 'v=1&preset=ramp&duration=20'
// (that commit takes the scenario before `--every`). It prints the speed of this build as a
// fraction of that one's (its CPU / this CPU), the median (min–max) of BENCH_REPS repetitions
// (default 7).
import { execFileSync, execSync } from 'node:child_process';
import { cpu } from './cpu.mjs';
import { existsSync, mkdirSync } from 'node:fs';

const BASELINE = 'f3ff4f2';
const root = new URL('../../', import.meta.url).pathname;
const reps = Number(process.env.BENCH_REPS ?? 7);
const src = `${root}target/baseline-${BASELINE}`;
if (!existsSync(`${src}/Cargo.toml`)) {
  mkdirSync(src, { recursive: true });
  execSync(`git -C '${root}' archive ${BASELINE} | tar -x -C '${src}'`, { stdio: 'inherit' });
}
execFileSync(
  'cargo',
  [
    'build',
    '--release',
    '-q',
    '--bin',
    'imlab',
    '--manifest-path',
    `${src}/Cargo.toml`,
    '--target-dir',
    `${src}/target`,
  ],
  { stdio: 'inherit' },
);

const run = 'v=1&preset=ramp&duration=20';
const baseline = [`${src}/target/release/imlab`, 'run', run, '--every', '100000000'];
const current = [`${root}target/release/imlab`, 'run', '--every', '100000000', run];

const ratios = [];
for (let r = 0; r < reps; r++) ratios.push(cpu(baseline) / cpu(current));
const median = [...ratios].sort((a, b) => a - b)[Math.floor(reps / 2)];
console.log(
  `the five-state path against ${BASELINE} (its CPU / this CPU, 400,000 steps, ${reps} repetitions; median (min–max)):`,
);
console.log(`  loop     ${median.toFixed(2)} (${Math.min(...ratios).toFixed(2)}–${Math.max(...ratios).toFixed(2)})`);
