// What the preset descriptions state, checked against the native core: a description (one line
// beside Run, and `imlab list`) names only the preset's settings and the paper's figures, and every
// conclusion it states holds on each of the noise draws 1..30. (The lessons' and the walkthrough's
// numbers are measurements of their own tables: tests/measurements.test.mjs.)
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { Core, checkText } from './claims.mjs';
import { SEEDS_30, unnoticedSwaps, withSeed as onSeed } from './claims.mjs';

const core = new Core();

// The presets' runs the checks read.
const SINE = 'v=1&preset=sine200';
const LOAD = 'v=1&preset=load-step&duration=3';
const LOAD_EST = 'v=1&preset=load-step-est';
const RR_PRESET = 'v=1&preset=rr-mismatch';
const RR_EST = 'v=1&preset=rr-mismatch-est&duration=4';
const EST_PRESET = 'v=1&preset=rr-mismatch-est';
const HIGH = 'v=1&preset=high-gain';
const DECAY = 'v=1&preset=decay';
const DECAY_HALF = `${DECAY}&ts=0.000025`;
const SINE_1RAD_RUN = 'v=1&preset=sine200-1rad';
const IFOC_HOLD = 'v=1&preset=ifoc-step&ref=constant&load.time=1&load.torque=2&duration=3';

/** `run` with the setting `extra` (none if empty) and noise seed `seed`. */
const variant = (run, extra, seed) => onSeed(extra ? `${run}&${extra}` : run, seed);
/** `f(m, run)`, and the run's trace dropped after it: traces of seconds are large. */
function withTrace(m, run, f) {
  try {
    return f(m, run);
  } finally {
    m.traces.delete(run);
  }
}
/** The final speed error of rr-mismatch on `seed` over `d` s, and whether it counts as settled. */
const rrError = (m, d, seed) => m.fig(variant(`${RR_PRESET}&duration=${d}`, '', seed), 'speed_error_final');
const rrSettled = (m, d, seed) =>
  m.fig(variant(`${RR_PRESET}&duration=${d}`, '', seed), 'speed_error_final_settled') === 1;
const digests = new Map();
/** `f(m, run)` computed once per `name` and run, with the run's trace dropped after it. */
function digest(m, run, name, f) {
  const key = `${name} ${run}`;
  if (!digests.has(key)) digests.set(key, withTrace(m, run, f));
  return digests.get(key);
}
/** load-step-est over its 0.3 s: the dip after the step and the largest error after it. */
const loadEstStats = (m, run) =>
  digest(m, run, 'load-est', (c) => ({
    dip: -c.stat(run, 'omega_err', 0.15, 0.3).min,
    after: c.stat(run, 'omega_err', 0.15, 0.3).maxAbs,
  }));
/**
 * `f(tr)` computed once per `name` and run, from every `every`-th sample of `run` (a run of seconds
 * read in full is slow and large): tr is {t, column(name), stat(name, t0, t1)}.
 */
function coarse(run, every, name, f) {
  const key = `${name} ${every} ${run}`;
  if (!digests.has(key)) {
    const cli = new URL('../target/release/imlab', import.meta.url).pathname;
    const [header, ...lines] = execFileSync(cli, ['run', '--every', String(every), run], { maxBuffer: 1 << 30 })
      .toString()
      .trim()
      .split('\n');
    const names = header.split(',');
    const rows = lines.map((l) => l.split(','));
    const column = (c) => Float64Array.from(rows, (r) => Number(r[names.indexOf(c)]));
    const t = column('t');
    const stat = (c, t0, t1) => {
      const v = [...column(c)].filter((_, i) => t[i] >= t0 - 1e-9 && t[i] <= t1 + 1e-9);
      return { min: Math.min(...v), max: Math.max(...v) };
    };
    digests.set(key, f({ t, column, stat }));
  }
  return digests.get(key);
}
/** rr-mismatch-est over `end` s: R̂_r's least and largest from 50 ms on. */
const rrEstStats = (run, end) =>
  coarse(run, 10, 'rr-est', (tr) => ({
    hatMin: tr.stat('rr_hat', 0.05, end).min,
    hatMax: tr.stat('rr_hat', 0.05, end).max,
  }));
/** decay (or a variant): V, its gain k1 (the four gains are equal), its value at the end and the errors' rate. */
function decayStats(m, run) {
  const tr = m.trace(run);
  const [t, V] = [tr.t, tr.column('lyapunov')];
  const k = Number(
    m
      .described(run)
      .find((l) => l.startsWith('k1 '))
      .split('=')[1]
      .trim()
      .split(/\s+/)[0],
  );
  const near = (x) => t.reduce((best, ti, i) => (Math.abs(ti - x) < Math.abs(t[best] - x) ? i : best), 0);
  return {
    k,
    V: (x) => V[near(x)],
    end: V[t.length - 1],
    /** The decay rate of √V (the errors' rate) from a to b (s). */
    rate: (a, b) => Math.log(V[near(a)] / V[near(b)]) / (2 * (b - a)),
  };
}

// The preset descriptions (`imlab list`), by preset. A description speaks of the preset, whatever
// its noise seed: it states no measured number, and each conclusion is checked on seeds 1..30.
/** The presets and their descriptions, as `imlab list` prints them. */
const presetList = () =>
  execFileSync(new URL('../target/release/imlab', import.meta.url).pathname, ['list'])
    .toString()
    .trim()
    .split('\n')
    .map((l) => l.match(/^(\S+)\s+(.*)$/).slice(1));
const PRESET_SPECS = {
  sine200: {
    givens: ['Paper Fig 2', '0.5 sin(2π·200 t)'],
    checks: [
      [
        "the current peaks above the motor's rated current",
        'claim',
        (m) =>
          SEEDS_30.every(
            (seed) => m.fig(onSeed(SINE, seed), 'current_peak') > m.fig(onSeed(SINE, seed), 'current_rated'),
          ),
      ],
    ],
  },
  step: { givens: ['Paper Fig 3', '0 → 0.5 rad/s step at 50 ms', 'a 200 Hz critically damped filter'], checks: [] },
  ramp: { givens: ['Paper Fig 4', 'trapezoid to 100 rad/s at ±400 rad/s²'], checks: [] },
  'sine200-1rad': {
    // No cause: with the preset's Euler EKF, removing the limit (vmax=100000) does not lower the
    // ratio (from init_err=0 over seeds 1..30: 4.3 to 4.5 without it, 4.2 to 4.4 with it), so the
    // text does not say the limit makes the error.
    givens: ['1 rad/s at 200 Hz', 'the 400 V limit'],
    checks: [
      // Over 10 % of the samples at the limit on every draw (at least 16 % over seeds 1..30).
      [
        'saturates the 400 V limit',
        'claim',
        (m) => SEEDS_30.every((seed) => m.fig(onSeed(SINE_1RAD_RUN, seed), 'saturated_share') > 0.1),
      ],
      // The ratio, seed by seed, is 3.6 to 4.0 over seeds 1..30 (3.5 to 4.1 over seeds 31..60).
      [
        "its tracking error is more than three times sine200's",
        'claim',
        (m) =>
          SEEDS_30.every(
            (seed) =>
              m.fig(onSeed(SINE_1RAD_RUN, seed), 'tracking_rms') > 3 * m.fig(onSeed(SINE, seed), 'tracking_rms'),
          ),
      ],
    ],
  },
  'sine200-rk4': { givens: ['Fig 2 with'], checks: [] },
  'rr-mismatch': {
    givens: ['Hold 50 rad/s', 'rotor resistance 10 % above', 'run it for 6 s'],
    checks: [
      // Far below at the preset's 0.3 s, still below after 1 s.
      [
        'the true speed recovers from the start-up over seconds',
        'claim',
        (m) => SEEDS_30.every((seed) => rrError(m, 0.3, seed) < -1 && rrError(m, 1, seed) < -0.1),
      ],
      // Above the reference and settled after 6 s, and the same after 20 s.
      [
        'settles above the reference',
        'claim',
        (m) =>
          SEEDS_30.every(
            (seed) =>
              rrError(m, 6, seed) > 0 &&
              rrSettled(m, 6, seed) &&
              rrSettled(m, 20, seed) &&
              Math.abs(rrError(m, 20, seed) - rrError(m, 6, seed)) < 0.1 * rrError(m, 6, seed),
          ),
      ],
    ],
  },
  'load-step': {
    givens: ['Hold 50 rad/s', 'an unknown 2 N m load step at 0.15 s'],
    checks: [
      [
        'that the 5-state EKF cannot see',
        'claim',
        (m) => SEEDS_30.every((seed) => m.fig(onSeed(LOAD, seed), 'speed_estimate_error_final') < -20),
      ],
    ],
  },
  decay: {
    givens: ['ω_d ≡ 0'],
    checks: [
      // The errors' rate (that of √V) over the first 6 ms within 3 % of the design, and from 6 to 12 ms well below it.
      [
        'the errors decay at the designed 1200/s',
        'claim',
        (m) => {
          const d = decayStats(m, DECAY);
          return d.k === 1200 && Math.abs(d.rate(0, 0.006) / d.k - 1) < 0.03 && d.rate(0.006, 0.012) < 0.7 * d.k;
        },
      ],
      [
        'then stop at a floor that shrinks with the sampling period',
        'claim',
        (m) =>
          decayStats(m, DECAY).V(0.015) / decayStats(m, DECAY).end < 1.02 &&
          decayStats(m, DECAY_HALF).end < 0.3 * decayStats(m, DECAY).end,
      ],
    ],
  },
  'ifoc-step': {
    givens: ['step to 40 rad/s'],
    // Holding zero speed under a 2 N m load from 1 s, the true speed leaves the speed the IFOC uses
    // by more than 5 rad/s within 3 s (by 9 to over 2,000 rad/s over seeds 1..30), and by over 20
    // times as much as holding 20 rad/s, where it stays within 1 rad/s.
    checks: [
      [
        'MRAS is blind near zero speed',
        'claim',
        () =>
          SEEDS_30.every((seed) => {
            const gap = (run) =>
              coarse(run, 10, 'mras', (tr) => {
                const [w, used] = [tr.column('omega'), tr.column('omega_used')];
                return Math.max(...tr.t.map((t, i) => (t >= 1 ? Math.abs(w[i] - used[i]) : 0)));
              });
            const [zero, twenty] = [
              gap(variant(IFOC_HOLD, 'ref.value=0', seed)),
              gap(variant(IFOC_HOLD, 'ref.value=20', seed)),
            ];
            return zero > 5 && twenty < 1 && zero > 20 * twenty;
          }),
      ],
    ],
  },
  'load-step-est': {
    givens: [],
    checks: [
      [
        'the speed holds through the unknown step with an exact model',
        'claim',
        (m) => SEEDS_30.every((seed) => loadEstStats(m, onSeed(LOAD_EST, seed)).after < 0.2),
      ],
      [
        "not with the motor's R_r 3 % below the model's",
        'claim',
        (m) => SEEDS_30.every((seed) => loadEstStats(m, variant(LOAD_EST, 'plant.rr=4.8015', seed)).dip > 1),
      ],
    ],
  },
  'rr-mismatch-est': {
    givens: [],
    checks: [
      [
        'no slow transient',
        'claim',
        (m) => SEEDS_30.every((seed) => Math.abs(m.fig(onSeed(EST_PRESET, seed), 'speed_error_final')) < 0.05),
      ],
      // Every sample over 4 s from the first 50 ms on, in which the estimate leaves its start,
      // within 5 % of the motor's 5.445 Ω (half the model's 10 % error): over seeds 1..30 it ends
      // 2 to 4 % high, and peaks just over 4 % high on some draws.
      [
        "R̂_r stays near the motor's value",
        'claim',
        () =>
          SEEDS_30.every((seed) => {
            const { hatMin, hatMax } = rrEstStats(onSeed(RR_EST, seed), 4);
            return Math.abs(hatMax / 5.445 - 1) < 0.05 && Math.abs(hatMin / 5.445 - 1) < 0.05;
          }),
      ],
    ],
  },
  'sine200-drive': { givens: ['Does 200 Hz survive', 'the 540 V inverter hexagon'], checks: [] },
  'high-gain': {
    givens: ['Gains 3000/s (2.5× the paper)'],
    // The Euler EKF's errors removed (RK4): the saturation goes.
    checks: [
      [
        "the Euler EKF's prediction errors through the gains saturate the 400 V limit",
        'cause',
        (m) =>
          SEEDS_30.every(
            (seed) =>
              m.fig(onSeed(HIGH, seed), 'saturated_share') > 0.9 &&
              m.fig(variant(HIGH, 'ekf=rk4', seed), 'saturated_share') < 0.01,
          ),
      ],
    ],
  },
};

test('the preset descriptions', () => {
  const list = presetList();
  assert.deepEqual(list.map(([name]) => name).sort(), Object.keys(PRESET_SPECS).sort());
  for (const [name, description] of list) assert.deepEqual(checkText(description, PRESET_SPECS[name], core), [], name);
});

test('a number moved to another place fails', () => {
  // Every swap of two numbers that the checks would not notice, by preset.
  const unnoticed = Object.fromEntries(
    presetList()
      .map(([name, description]) => [`preset: ${name}`, unnoticedSwaps(description, PRESET_SPECS[name], core)])
      .filter(([, swaps]) => swaps.length),
  );
  assert.deepEqual(unnoticed, {});
});
