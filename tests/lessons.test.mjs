// What the walkthrough and the preset descriptions state, checked against the core: every number
// in their texts is either a setting of a run (a "given") or a figure that a named run of the
// native core reproduces within a named tolerance. A number changed in the text, or a figure that
// drifts in the core, fails the test. (The lessons' numbers are measurements of their own table:
// tests/measurements.test.mjs.)
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { SECTIONS, STABILITY_CAUSES } from '../web/teaching/walkthrough-text.js';
import { Core, checkText } from './claims.mjs';
import { SEEDS, unnoticedSwaps, withSeed as onSeed } from './claims.mjs';
import { readFileSync } from 'node:fs';
import { initSync, Simulation } from '../dist/pkg/imlab.js';

initSync({ module: readFileSync(new URL('../dist/pkg/imlab_bg.wasm', import.meta.url)) });

const core = new Core();

// Runs the walkthrough's and the presets' figures come from.
const STEP = 'v=1&preset=step';
const SINE = 'v=1&preset=sine200';
const RR = 'v=1&preset=rr-mismatch&duration=6';
const LOAD = 'v=1&preset=load-step&duration=3';
const LOAD_EST = 'v=1&preset=load-step-est';
const RR_EST = 'v=1&preset=rr-mismatch-est&duration=4';
const HIGH = 'v=1&preset=high-gain';

/**
 * The peaks of |d̃2| and |d̃4| of `run` from `from` s on, and when |d̃2| peaks, as the core evaluates
 * them from the simulated truth (`Simulation.disturbances`, the walkthrough's plots); each run once.
 */
const peaksOf = new Map();
function disturbancePeaks(run, from = 0.015) {
  const key = `${run} ${from}`;
  if (!peaksOf.has(key)) {
    const sim = new Simulation(run);
    while (!sim.finished) sim.step(1_000_000);
    const [t, d2, d4] = sim.disturbances(from, Number.MAX_VALUE, 1 << 30);
    sim.free();
    let peak = { d2: 0, d4: 0, at: NaN };
    t.forEach((ti, i) => {
      if (Math.abs(d2[i]) > peak.d2) peak = { ...peak, d2: Math.abs(d2[i]), at: ti };
      peak.d4 = Math.max(peak.d4, Math.abs(d4[i]));
    });
    peaksOf.set(key, peak);
  }
  return peaksOf.get(key);
}

/** Field `key` of `run` as `imlab describe` prints it. */
const fieldOf = (m, run, key) =>
  Number(
    m
      .described(run)
      .find((l) => l.startsWith(`${key} `))
      .split('=')[1]
      .trim()
      .split(/\s+/)[0],
  );

/** a7 + a8 of the model of `run` (1/s), from the motor parameters by the lumped forms of (2). */
function a7PlusA8(m, run) {
  const p = (key) => fieldOf(m, run, `model.${key}`);
  const sigma = p('ls') - p('m') ** 2 / p('lr');
  const alpha = p('rr') / p('lr');
  const beta = p('m') / (sigma * p('lr'));
  return p('rs') / sigma + alpha * beta * p('m') + alpha;
}

// The walkthrough and the preset descriptions: figures over seeds 1–10, and the
// model errors a conclusion is checked against, both signs (the motor's R_r ±10 %, the model's
// inertia ±20 %).
const RR_HIGH = 'plant.rr=5.445';
const RR_LOW = 'plant.rr=4.455';
const RR_PRESET = 'v=1&preset=rr-mismatch';
const EST_PRESET = 'v=1&preset=rr-mismatch-est';
const DECAY = 'v=1&preset=decay';
const SINE_1RAD_RUN = 'v=1&preset=sine200-1rad';
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
/** The final speed error of rr-mismatch (with `extra`, on `seed`) over `d` s. */
const rrError = (m, d, extra, seed) => m.fig(variant(`${RR_PRESET}&duration=${d}`, extra, seed), 'speed_error_final');
/** The time constant of rr-mismatch's slow mode from 1 s to 2 s, about the error at 6 s (s), read every 10 ms. */
function rrTau(m, extra, seed) {
  return coarse(variant(`${RR_PRESET}&duration=6`, extra, seed), 200, 'tau', (tr) => {
    const end = tr.at('omega_err', 6);
    return 1 / Math.log((tr.at('omega_err', 1) - end) / (tr.at('omega_err', 2) - end));
  });
}
const digests = new Map();
/** `f(m, run)` computed once per `name` and run, with the run's trace dropped after it. */
function digest(m, run, name, f) {
  const key = `${name} ${run}`;
  if (!digests.has(key)) digests.set(key, withTrace(m, run, f));
  return digests.get(key);
}
/** load-step-est over its 0.3 s: the dip after the step, the time back within 0.05 rad/s, the load estimate and its band. */
const loadEstStats = (m, run) =>
  digest(m, run, 'load-est', (c) => ({
    dip: -c.stat(run, 'omega_err', 0.15, 0.3).min,
    back: c.recovery(run, 0.15, 0.05),
    load: c.stat(run, 'load_hat', 0.2, 0.3).mean,
    band: c.at(run, 'load_band', 0.3),
    before: c.stat(run, 'omega_err', c.fig(run, 'transient_end'), 0.15).maxAbs,
    after: c.stat(run, 'omega_err', 0.15, 0.3).maxAbs,
  }));
/**
 * `f(tr)` computed once per `name` and run, from every `every`-th sample of `run` (a run of seconds
 * read in full is slow and large): tr is {t, column(name), stat(name, t0, t1), at(name, t)}.
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
    const near = (x) => t.reduce((best, ti, i) => (Math.abs(ti - x) < Math.abs(t[best] - x) ? i : best), 0);
    const stat = (c, t0, t1) => {
      const v = [...column(c)].filter((_, i) => t[i] >= t0 - 1e-9 && t[i] <= t1 + 1e-9);
      return {
        mean: v.reduce((a, x) => a + x, 0) / v.length,
        rms: Math.sqrt(v.reduce((a, x) => a + x * x, 0) / v.length),
        min: Math.min(...v),
        max: Math.max(...v),
        maxAbs: Math.max(...v.map(Math.abs)),
      };
    };
    digests.set(key, f({ t, column, stat, at: (c, x) => column(c)[near(x)] }));
  }
  return digests.get(key);
}
/** A 3 s run's last second (every 0.5 ms): the RMS of ω − ω_d, and the load and R_r estimates over its last 0.1 s. */
const tail = (m, run) =>
  coarse(run, 10, 'tail', (tr) => ({
    rms: tr.stat('omega_err', 2, 3).rms,
    load: tr.stat('load_hat', 2.9, 3).mean,
    rr: tr.stat('rr_hat', 2.9, 3).mean,
  }));
/** rr-mismatch-est over `end` s: R̂_r and its band over the last 0.1 s, the band over parts of the second to fourth second, and R̂_r's least and largest from 50 ms on. */
const rrEstStats = (m, run, end) =>
  coarse(run, 10, 'rr-est', (tr) => ({
    hat: tr.stat('rr_hat', end - 0.1, end).mean,
    band: tr.stat('rr_band', end - 0.1, end).mean,
    band14: tr.stat('rr_band', 1, 4).mean,
    band115: tr.stat('rr_band', 1, 1.5).mean,
    band354: tr.stat('rr_band', 3.5, 4).mean,
    hatMin: tr.stat('rr_hat', 0.05, end).min,
    hatMax: tr.stat('rr_hat', 0.05, end).max,
  }));

// The walkthrough's statements of fact (prose and notes of each section), by section id.
/**
 * The RMS of the recorded ż3 (from successive samples) against −k3·z3 + z4 averaged over the
 * interval, from `from` (s) on, over the RMS of ż3, in %; k3 = 1200/s as on step.
 */
const step3Miss = (m, run, from) =>
  digest(m, run, 'step3', (c) => {
    const tr = c.trace(run);
    const [z3, z4] = [tr.column('z3'), tr.column('z4')];
    let [miss, rate] = [0, 0];
    for (let i = 0; i + 1 < z3.length; i++) {
      if (tr.t[i] < from) continue;
      const d = (z3[i + 1] - z3[i]) / (tr.t[i + 1] - tr.t[i]);
      const model = 0.5 * (-1200 * z3[i] + z4[i] + (-1200 * z3[i + 1] + z4[i + 1]));
      miss += (d - model) ** 2;
      rate += d * d;
    }
    return 100 * Math.sqrt(miss / rate);
  });
/** The largest commanded voltage component of `run`'s first second (V), and the last time the limit changed it (s). */
const commands = (m, run) =>
  digest(m, run, 'commands', (c) => ({
    peak: Math.max(c.stat(run, 'u_a_cmd', 0, 1).maxAbs, c.stat(run, 'u_b_cmd', 0, 1).maxAbs),
    lastClipped: c.lastSaturated(run),
  }));
/** decay (or a variant): V against its bound V(0)·e^(−λt), λ = 2·k1 (the four gains are equal), and the z_i at the end. */
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
  const bound = (i) => V[0] * Math.exp(-2 * k * t[i]);
  const near = (x) => t.reduce((best, ti, i) => (Math.abs(ti - x) < Math.abs(t[best] - x) ? i : best), 0);
  const last = t.length - 1;
  return {
    k,
    V: (x) => V[near(x)],
    end: V[last],
    firstAbove: t.find((_, i) => V[i] > bound(i) * (1 + 1e-9)),
    aboveAtEnd: V[last] / bound(last),
    z: ['z1', 'z2', 'z3', 'z4'].map((c) => tr.column(c)[last]),
    /** The decay rate of √V (the errors' rate) from a to b (s). */
    rate: (a, b) => Math.log(V[near(a)] / V[near(b)]) / (2 * (b - a)),
  };
}
const DECAY_HALF = `${DECAY}&ts=0.000025`;
const SIN_NO_LIMIT = 'v=1&preset=sine200&vmax=100000';

const SECTION_SPECS = {
  model: { givens: ['contains 1/J', 'a1 = 3n_pM/(2JL_r)', 'σ = 1 − M²/(L_sL_r)'], checks: [] },
  ekf: {
    givens: [
      'forward Euler (10)',
      'the Jacobian (11)',
      'the general form (4)',
      'their ±2σ band about 95 % of the time',
      'averaging 2',
      'Section 3.1 names',
      'their ±2σ bands from P',
      'Printed (13)',
      'u_{k|k−1}',
      'u_{k−1}, which (10) uses',
      'the covariance update (19)',
    ],
    checks: [
      [
        'The Euler predictor cannot follow 200 Hz currents',
        'claim',
        (m) =>
          SEEDS.every(
            (seed) =>
              m.fig(onSeed(SINE, seed), 'mean_nis') > 10 && m.fig(variant(SINE, 'ekf=rk4', seed), 'mean_nis') < 2.1,
          ),
      ],
      [
        'a rotor-resistance state under an unknown load takes the load for a resistance',
        'claim',
        (m) => SEEDS.every((seed) => tail(m, variant(LOAD, 'ekf.rr=1', seed)).rr > 1.05 * 4.95),
      ],
    ],
  },
  bridge: {
    givens: [
      'the general form (4)',
      'the model (2)',
      'the prior residual y_k − Cx̂_{k|k−1} (15)',
      '(I − CK_k)(y_k − Cx̂_{k|k−1})',
      '(5)',
      'Subtracting (4) from (2)',
      'in step 2 (ż2 holds',
      'in step 4 (ż4 holds',
      'Steps 1 and 3',
      'with x̃1 = x̃4 = x̃5 = 0',
    ],
    checks: [],
  },
  step1: {
    givens: [
      'Step 1',
      'Printed (31)',
      'the first line of (4)',
      'the open loop (23)',
      'the shortfall z2 (24)',
      'Then (25) holds',
      'v1 = v1a + v1s (26)',
      'The feedforward v1a (27)',
      'v1s = −k1s1·z1 (28)',
      'leaves (29)',
      'Along (29)',
      'Steps 1 and 2',
      'steps 3 and 4',
      'which step 2 cancels',
      'Step 2 needs',
      'Differentiate (30)',
      '(section 3)',
    ],
    checks: [],
  },
  step2: {
    givens: [
      'Step 2 makes',
      '(32) as printed',
      'of (36) counts it',
      'h2²z2/(4ε2)',
      'Differentiate (24)',
      'are those of (4)',
      'is (31)',
      '(32) follows',
      'only through d̃2 (33)',
      'with a projection (7)–(9)',
      'With R_r 10 % above, the flux runs off',
      'for (38) to dominate it',
      'v2 = v2a + v2s (34)',
      'v2s = −k2s1·z2 + v2s2 (36)',
      '(38) dominates',
      'V_s2 = ½(z1² + z2²) (39)',
      'x̂̇ is no longer (4), nor ψ2–ψ4',
      '+ ε2 (40)',
      'Printed (35)',
    ],
    checks: [
      ['For the paper’s motor a7 + a8 = [232.7] /s', 0.05, (m) => a7PlusA8(m, STEP)],
      ['so k2s1 = [967.3] /s when k2 = 1200 /s', 0.05, (m) => fieldOf(m, STEP, 'k2') - a7PlusA8(m, STEP)],
      [
        'from 15 ms on, |d̃2| peaks at [3,900] to [4,700] rad/s³ over seeds 1–10',
        { range: 50, seeds: SEEDS },
        (m, seed) => disturbancePeaks(onSeed(STEP, seed)).d2,
      ],
      [
        'at the speed step (t = 0.05 s)',
        'claim',
        () => SEEDS.every((seed) => Math.abs(disturbancePeaks(onSeed(STEP, seed)).at - 0.0525) <= 0.0025),
      ],
      [
        'With the motor’s J 20 % above the model’s the peak is [6,400] to [7,400] rad/s³',
        { range: 100, seeds: SEEDS },
        (m, seed) => disturbancePeaks(variant(STEP, 'plant.j=0.024', seed)).d2,
      ],
      [
        'with it 20 % below [5,500] to [6,200]',
        { range: 100, seeds: SEEDS },
        (m, seed) => disturbancePeaks(variant(STEP, 'plant.j=0.016', seed)).d2,
      ],
      [
        'with the motor’s R_r 10 % below the model’s, [51,000] to [58,000] rad/s³',
        { range: 1000, seeds: SEEDS },
        (m, seed) => disturbancePeaks(variant(STEP, 'plant.rr=4.455', seed)).d2,
      ],
      [
        'These peaks are the same over a 1 s run',
        'claim',
        () =>
          SEEDS.every((seed) =>
            ['', 'plant.j=0.024', 'plant.j=0.016', 'plant.rr=4.455'].every(
              (extra) =>
                disturbancePeaks(variant(STEP, extra, seed)).d2 ===
                disturbancePeaks(variant(STEP, `${extra}${extra ? '&' : ''}duration=1`, seed)).d2,
            ),
          ),
      ],
      [
        'to [5.5] to [13.2] Wb by the end of the preset’s 0.1 s',
        { range: 0.1, seeds: SEEDS },
        (m, seed) => m.fig(variant(STEP, 'plant.rr=5.445', seed), 'flux_error_final') + Math.SQRT1_2,
      ],
      [
        'and [28] to [33] Wb after 1 s',
        { range: 0.5, seeds: SEEDS },
        (m, seed) => m.fig(variant(STEP, 'plant.rr=5.445&duration=1', seed), 'flux_error_final') + Math.SQRT1_2,
      ],
      [
        'within the 0.1 s |d̃2| reaches [57] to [590] million rad/s³',
        { range: 5, seeds: SEEDS },
        (m, seed) => disturbancePeaks(variant(STEP, 'plant.rr=5.445', seed)).d2 / 1e6,
      ],
    ],
  },
  step3: {
    givens: [
      'Step 3',
      'the virtual control 2a10(x2·x̂4 + x3·x̂5)',
      'from 15 ms on (after the start-up)',
      '− ψ_d (42)',
      'needs only (4)',
      'ż3 = 2x̂4·x̂̇4 + 2x̂5·x̂̇5',
      'from ψ3 (43)',
      'v3 = −ψ3 − k3·z3 (45)',
      'z4 (46)',
      'step 4 cancels',
      'the next error z4 (44)',
      '(42) subtracts ψ_d',
      'read literally is 0.5 Wb (0.25 Wb²)',
      'state “ϕ_d = 0.5” as',
      'as (42) uses it',
      'initial flux [0.5, 0.5]',
    ],
    checks: [
      [
        'the recorded z3 misses it by [71] to [73] % of the RMS of ż3 over seeds 1–10',
        { range: 0.5, seeds: SEEDS },
        (m, seed) => step3Miss(m, onSeed(STEP, seed), 0.015),
      ],
      [
        'by [9.3] % without noise (noise=0)',
        { tol: 0.05, seeds: SEEDS },
        (m, seed) => step3Miss(m, variant(STEP, 'noise=0', seed), 0.015),
      ],
      [
        'the measurement noise enters through the innovations',
        'cause',
        (m) =>
          SEEDS.every(
            (seed) =>
              step3Miss(m, variant(STEP, 'noise=0', seed), 0.015) < 0.2 * step3Miss(m, onSeed(STEP, seed), 0.015),
          ),
      ],
      [
        'by [2.7] % with the perfect observer (perfect=1)',
        { tol: 0.05, seeds: SEEDS },
        (m, seed) => step3Miss(m, variant(STEP, 'perfect=1', seed), 0.015),
      ],
      ['psi_d = [0.5] Wb²', 0, (m) => fieldOf(m, STEP, 'psi_d')],
      ['a flux modulus |φ| = [0.707] Wb', 0.0005, (m) => Math.sqrt(fieldOf(m, STEP, 'psi_d'))],
      [
        'whose miss halves with Ts',
        'claim',
        (m) =>
          Math.abs(
            step3Miss(m, `${STEP}&perfect=1&ts=0.000025`, 0.015) / step3Miss(m, `${STEP}&perfect=1`, 0.015) - 0.5,
          ) < 0.05,
      ],
    ],
  },
  step4: {
    givens: [
      'Step 4 drives',
      '(the first line of step 3), not in the form (43)',
      'the printed (47) holds with L̇ = 0',
      '2(l41·x̂4 + l51·x̂5) and 2(l42·x̂4 + l52·x̂5)',
      '(section 3)',
      '+ v4s2 (49)–(51)',
      'and (52) follows',
      'the printed (47) regrouped',
      'writes 2a10(l21·x̃2·x̂4 + …) for 2a10(x̂4·si2 + x̂5·si3)',
      'v4 = 2a10·b(x̂4·u1 + x̂5·u2)',
      'the decoupling matrix (54)',
      'not zero (55)',
      'the paper gives only a 400 V limit; the box (vlimit=box) clips each component to ±400 V',
      'Printed (48)',
      'for (53) to dominate it',
    ],
    checks: [
      [
        'peaks at [1,600] to [3,400] Wb²/s² on step with an exact model, from 15 ms on, over seeds 1–10',
        { range: 50, seeds: SEEDS },
        (m, seed) => disturbancePeaks(onSeed(STEP, seed)).d4,
      ],
      [
        '([1,900] to [3,400] over a 1 s run)',
        { range: 50, seeds: SEEDS },
        (m, seed) => disturbancePeaks(variant(STEP, 'duration=1', seed)).d4,
      ],
      [
        'tens of kilovolts',
        'claim',
        (m) =>
          SEEDS.every(
            (seed) => commands(m, onSeed(STEP, seed)).peak > 1e4 && commands(m, onSeed(RR_PRESET, seed)).peak > 1e4,
          ),
      ],
      [
        '[11] to [32] kV at its peak on step',
        { range: 0.5, seeds: SEEDS },
        (m, seed) => 1e-3 * commands(m, onSeed(STEP, seed)).peak,
      ],
      [
        '[34] to [166] kV on rr-mismatch over seeds 1–10',
        { range: 0.5, seeds: SEEDS },
        (m, seed) => 1e-3 * commands(m, onSeed(RR_PRESET, seed)).peak,
      ],
      [
        'on rr-mismatch it stays beyond the limit for the first [10] to [19] ms',
        { range: 0.5, seeds: SEEDS },
        (m, seed) => 1e3 * commands(m, onSeed(RR_PRESET, seed)).lastClipped,
      ],
    ],
  },
  stability: {
    givens: [
      'With the EKF’s 10 % initial error',
      'sine200 with vmax=100000',
      'z4²) (58)',
      '+ z4(v4s2 + d̃4) (60)',
      'h2 = δ_d2 of (38), the bound the paper derives for d̃2 from Assumption 4.2’s',
      'h2²z2²/(4ε2)',
      'Σk_i·z_i² ≥ min(k_i)·Σz_i² = 2·min(k_i)·V',
      'integrating from 0 to t gives (59)',
      'differ too: (59) holds',
    ],
    checks: [
      [
        'the run ends [6,100] to [6,500] rad/s off, on either side',
        { range: 50, seeds: SEEDS },
        (m, seed) => Math.abs(m.fig(onSeed(SIN_NO_LIMIT, seed), 'speed_error_final')),
      ],
      [
        'on either side',
        'claim',
        (m) =>
          new Set(SEEDS.map((seed) => Math.sign(m.fig(onSeed(SIN_NO_LIMIT, seed), 'speed_error_final')))).size === 2,
      ],
      [
        'with the flux at [8.7] to [9.3] Wb over seeds 1–10',
        { range: 0.1, seeds: SEEDS },
        (m, seed) => m.fig(onSeed(SIN_NO_LIMIT, seed), 'flux_error_final') + Math.SQRT1_2,
      ],
      [
        'the page reports it as a run that ran away',
        'claim',
        (m) => SEEDS.every((seed) => m.ranAway(onSeed(SIN_NO_LIMIT, seed))),
      ],
      [
        'From a correct initial estimate (init_err=0) the same run tracks to [0.013] to [0.014] rad/s RMS with an exact model',
        { range: 0.001, seeds: SEEDS },
        (m, seed) => m.fig(variant(SIN_NO_LIMIT, 'init_err=0', seed), 'tracking_rms'),
      ],
      [
        'From a correct initial estimate (init_err=0) the same run tracks',
        'claim',
        (m) => SEEDS.every((seed) => !m.ranAway(variant(SIN_NO_LIMIT, 'init_err=0', seed))),
      ],
      [
        'but with the motor’s R_r 10 % above the model’s it fails even so',
        'claim',
        (m) => SEEDS.every((seed) => m.fig(variant(SIN_NO_LIMIT, `init_err=0&${RR_HIGH}`, seed), 'tracking_rms') > 5),
      ],
    ],
  },
};

for (const section of SECTIONS) {
  test(`walkthrough: ${section.title}`, () => {
    const text = [...section.prose, section.note ?? '', ...(section.shows ?? [])].join('\n');
    assert.deepEqual(checkText(text, SECTION_SPECS[section.id], core), []);
  });
}

// What the stability section adds when V leaves the bound, by cause: the note for a perfect
// observer, checked on decay (no noise, equal gains, ε = 0).
const NOTE_SPECS = {
  sampling: {
    givens: ['d̃2 = d̃4 = 0'],
    checks: [
      [
        'proportional to Ts in the z_i',
        'claim',
        (m) => decayStats(m, DECAY).z.every((z, i) => Math.abs(decayStats(m, DECAY_HALF).z[i] / z - 0.5) < 0.05),
      ],
      [
        'on decay V stays under the bound for about the first 5 ms',
        'claim',
        (m) => decayStats(m, DECAY).firstAbove > 0.0045 && decayStats(m, DECAY).firstAbove < 0.0055,
      ],
      [
        'then stops at a floor, reached by about 15 ms',
        'claim',
        (m) => {
          const d = decayStats(m, DECAY);
          return d.V(0.015) / d.end < 1.02 && d.V(0.012) / d.end > 1.1;
        },
      ],
      [
        'so that V ends about 10¹¹ times above it',
        'claim',
        (m) => Math.abs(Math.log10(decayStats(m, DECAY).aboveAtEnd) - 11) < 0.5,
      ],
      [
        'halving Ts quarters the floor',
        'claim',
        (m) => Math.abs(decayStats(m, DECAY_HALF).end / decayStats(m, DECAY).end - 0.25) < 0.03,
      ],
      [
        '(10⁶ times with the motor’s R_r 10 % off either way)',
        'claim',
        (m) =>
          [RR_HIGH, RR_LOW].every(
            (extra) =>
              Math.abs(Math.log10(decayStats(m, `${DECAY}&${extra}`).end / decayStats(m, DECAY).end) - 6) < 0.5,
          ),
      ],
    ],
  },
};

test('walkthrough: the stability note for a perfect observer', () => {
  assert.deepEqual(checkText(STABILITY_CAUSES.sampling, NOTE_SPECS.sampling, core), []);
});

// The preset descriptions (`imlab list`), by preset. A description speaks of the preset, whatever
// its noise seed: a figure the noise moves is stated as its range, or checked, over seeds 1–10.
/** The presets and their descriptions, as `imlab list` prints them. */
const presetList = () =>
  execFileSync(new URL('../target/release/imlab', import.meta.url).pathname, ['list'])
    .toString()
    .trim()
    .split('\n')
    .map((l) => l.match(/^(\S+)\s+(.*)$/).slice(1));
const IFOC_HOLD = 'v=1&preset=ifoc-step&ref=constant&load.time=1&load.torque=2&duration=3';
const PRESET_SPECS = {
  sine200: {
    givens: ['Paper Fig 2', '0.5 sin(2π·200 t)'],
    checks: [
      [
        "the current peaks at [1.8] to [2.4] times the motor's rated current",
        { range: 0.1, seeds: SEEDS },
        (m, seed) => m.fig(onSeed(SINE, seed), 'current_peak') / m.fig(onSeed(SINE, seed), 'current_rated'),
      ],
    ],
  },
  step: { givens: ['Paper Fig 3', '0 → 0.5 rad/s step at 50 ms', 'a 200 Hz critically damped filter'], checks: [] },
  ramp: { givens: ['Paper Fig 4', 'trapezoid to 100 rad/s at ±400 rad/s²'], checks: [] },
  'sine200-1rad': {
    givens: ['1 rad/s at 200 Hz', 'the 400 V limit'],
    checks: [
      ['saturates', 'claim', (m) => SEEDS.every((seed) => m.fig(onSeed(SINE_1RAD_RUN, seed), 'saturated_share') > 0.1)],
      [
        'tracking suffers',
        'claim',
        (m) =>
          SEEDS.every(
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
      [
        'the true speed recovers from the start-up',
        'claim',
        (m) =>
          SEEDS.every(
            (seed) => rrError(m, 0.3, '', seed) < -1 && m.fig(onSeed(RR, seed), 'speed_error_final_settled') === 1,
          ),
      ],
      ['with a time constant of about [0.6] s', { tol: 0.05, seeds: SEEDS }, (m, seed) => rrTau(m, '', seed)],
      ['ends [0.12] rad/s high', { tol: 0.01, seeds: SEEDS }, (m, seed) => rrError(m, 6, '', seed)],
    ],
  },
  'load-step': {
    givens: ['Hold 50 rad/s', 'an unknown 2 N m load step at 0.15 s'],
    checks: [
      [
        'that the 5-state EKF cannot see',
        'claim',
        (m) => SEEDS.every((seed) => m.fig(onSeed(LOAD, seed), 'speed_estimate_error_final') < -20),
      ],
    ],
  },
  decay: {
    givens: ['ω_d ≡ 0'],
    checks: [
      // The errors' rate (that of √V) over the first 6 ms within 3 % of the design, and from 6 to 12 ms well below it.
      [
        'the errors decay at the designed 1200/s for about 6 ms',
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
    // Holding zero speed under a 2 N m load from 1 s, the true speed leaves the speed the IFOC uses by more than 50 rad/s within 3 s; at 20 rad/s by under 1.
    checks: [
      [
        'MRAS is blind near zero speed',
        'claim',
        () =>
          SEEDS.every((seed) => {
            const gap = (run) =>
              coarse(run, 10, 'mras', (tr) => {
                const [w, used] = [tr.column('omega'), tr.column('omega_used')];
                return Math.max(...tr.t.map((t, i) => (t >= 1 ? Math.abs(w[i] - used[i]) : 0)));
              });
            return (
              gap(variant(IFOC_HOLD, 'ref.value=0', seed)) > 50 && gap(variant(IFOC_HOLD, 'ref.value=20', seed)) < 1
            );
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
        (m) => SEEDS.every((seed) => loadEstStats(m, onSeed(LOAD_EST, seed)).after < 0.2),
      ],
      [
        "not with the motor's R_r 3 % below the model's",
        'claim',
        (m) => SEEDS.every((seed) => loadEstStats(m, variant(LOAD_EST, 'plant.rr=4.8015', seed)).dip > 1),
      ],
    ],
  },
  'rr-mismatch-est': {
    givens: [],
    checks: [
      [
        'no slow transient',
        'claim',
        (m) => SEEDS.every((seed) => Math.abs(m.fig(onSeed(EST_PRESET, seed), 'speed_error_final')) < 0.05),
      ],
      // Every sample from the first 50 ms on, in which the estimate leaves its start.
      [
        "R̂_r within 4 % of the motor's value over 4 s",
        'claim',
        (m) =>
          SEEDS.every((seed) => {
            const { hatMin, hatMax } = rrEstStats(m, onSeed(RR_EST, seed), 4);
            return Math.abs(hatMax / 5.445 - 1) < 0.04 && Math.abs(hatMin / 5.445 - 1) < 0.04;
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
          SEEDS.every(
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
  const texts = [
    ...SECTIONS.map((s) => [
      `walkthrough: ${s.title}`,
      [...s.prose, s.note ?? '', ...(s.shows ?? [])].join('\n'),
      SECTION_SPECS[s.id],
    ]),
    ...Object.entries(NOTE_SPECS).map(([cause, spec]) => [`stability note: ${cause}`, STABILITY_CAUSES[cause], spec]),
    ...presetList().map(([name, description]) => [`preset: ${name}`, description, PRESET_SPECS[name]]),
  ];
  // Every swap of two numbers that the checks would not notice, by text.
  const unnoticed = Object.fromEntries(
    texts.map(([name, text, spec]) => [name, unnoticedSwaps(text, spec, core)]).filter(([, swaps]) => swaps.length),
  );
  assert.deepEqual(unnoticed, {});
});
