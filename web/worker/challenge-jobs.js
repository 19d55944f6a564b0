// The worker's challenge jobs (their fields and results are in protocol.js's Jobs): each parses
// the challenge text it is given (the core's Challenge), so any worker of a pool can take any of
// them. Every check and figure comes from the core. A bad challenge throws the core's message,
// which the worker returns as the job's error.
import {
  Challenge,
  challenge_builtins,
  challenge_compose,
  challenge_figures,
  challenge_measure,
  grade_class,
  grade_link,
  Simulation,
} from '../../pkg/imlab.js';

/** @import {RawJobs as Jobs} from './protocol.js' */
/** @import {Measures} from '../../pkg/imlab.js' */

/**
 * The kinds of the challenge jobs: the challenges' and the grading's.
 * @typedef {Extract<keyof Jobs, `challenge${string}` | `grade-${string}`>} ChallengeKind
 */

/**
 * `f(challenge)` on the challenge `text` opens (a challenge link, a submission link, a built-in's
 * name), freed afterwards.
 * @template T
 * @param {string} text
 * @param {(challenge: Challenge) => T} f
 * @returns {T}
 */
function withChallenge(text, f) {
  const challenge = Challenge.from_link(text);
  try {
    return f(challenge);
  } finally {
    challenge.free();
  }
}

/**
 * Runs `scenario` to its end in one call and measures it; a run that stops early is measured
 * as far as it went, and the measures say why it failed.
 * @param {string} scenario
 * @returns {Measures}
 */
function measureRun(scenario) {
  const sim = new Simulation(scenario);
  try {
    try {
      while (!sim.finished) sim.step_for(1e9);
    } catch (e) {
      // A run that fails stops here: the core keeps why, and its measures say it.
      if (e instanceof WebAssembly.RuntimeError) throw e;
    }
    return challenge_measure(sim);
  } finally {
    sim.free();
  }
}

/** @type {{[K in ChallengeKind]: (d: Jobs[K]['req']) => Jobs[K]['result']}} */
export const CHALLENGE_JOBS = {
  challenge: (d) => withChallenge(d.text, (c) => c.describe()),
  'challenge-submission': (d) => withChallenge(d.text, (c) => c.submission(d.submission)),
  'challenge-tries': (d) => withChallenge(d.text, (c) => c.submission_of(d.tries)),
  'challenge-compose': (d) => challenge_compose(d.parts),
  'challenge-designs': (d) => withChallenge(d.text, (c) => c.search_designs(d.max)),
  'challenge-judge': (d) => withChallenge(d.text, (c) => c.judge(d.runs)),
  'challenge-run': (d) => measureRun(d.scenario),
  'challenge-builtins': () => challenge_builtins(),
  'challenge-figures': () => challenge_figures(),
  'grade-class': (d) => grade_class(d.text, d.bytes),
  'grade-link': (d) => grade_link(d.text, d.row),
};
