// The worker's stateless jobs, by kind (see Jobs in protocol.js): each takes its fields and
// returns what the core computed, so any worker of a pool can take any of them. They run on the
// core built with its tools (pkg/), which the worker loads with this module on its first job.
import initTools, {
  design_lines,
  law_language,
  law_preview,
  law_verdicts,
  motor_example,
  motor_from_tests,
  panic_message,
  robust_cells,
  robust_csv,
  robust_figures,
  robust_parts,
  robust_plan,
  robust_run,
  scenario_differences,
  seed_bands,
  seed_range,
  seed_run,
  seeds_csv,
  sweep_csv,
  sweep_plan,
  sweep_plan_of,
  sweep_point,
  sweep_summary,
} from '../../pkg/imlab.js';
import { CHALLENGE_JOBS } from './challenge-jobs.js';

export { initTools, panic_message };

/** @typedef {import('./protocol.js').RawJobs} Jobs */

/** @type {{[K in keyof Jobs]: (d: Jobs[K]['req']) => Jobs[K]['result']}} */
export const JOBS = {
  'sweep-plan': (d) => sweep_plan(d.text),
  'sweep-plan-of': (d) => sweep_plan_of(d.numbers, d.variants),
  sweep: (d) => sweep_point(d.scenario, d.variant, d.freq, d.amp, d.duration, d.offset),
  'seed-range': (d) => [...seed_range(d.first, d.n)],
  seed: (d) => seed_run(d.scenario, d.seed, d.every),
  bands: (d) => seed_bands(d.runs),
  summary: (d) => sweep_summary(d.points),
  'sweep-csv': (d) => sweep_csv(d.points),
  'seeds-csv': (d) => seeds_csv(d.results),
  'map-parts': (d) => robust_parts(d.text),
  'map-plan': (d) => ({ map: robust_plan(d.scenario, d.axes, d.seeds), figures: robust_figures() }),
  'map-run': (d) => robust_run(d.scenario, d.seed),
  'map-cells': (d) => robust_cells(d.map, d.runs),
  'map-csv': (d) => robust_csv(d.map, d.cells),
  'law-language': () => law_language(),
  'law-preview': (d) => law_preview(d.step, d.text),
  'law-verdicts': (d) => law_verdicts(d.scenario),
  design: (d) => design_lines(d.scenario),
  motor: (d) => motor_from_tests(d.entry),
  'motor-example': () => motor_example(),
  'scenario-differences': (d) => scenario_differences(d.from, d.text),
  ...CHALLENGE_JOBS,
};
