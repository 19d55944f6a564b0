// Fuzz test of the WASM core's bindings in Node: thousands of seeded, generated inputs (valid
// scenarios with random fields, mutations of them, random bytes, key/value soups, long strings,
// control characters, junk objects) through every exported function. A bad input must give a
// clean error (a thrown message); a trap (WebAssembly.RuntimeError) would leave the page's worker
// unusable, so any trap fails the test.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import {
  initSync,
  columns,
  Comparison,
  describe,
  sweep_plan,
  presets,
  recover,
  seed_bands,
  seed_run,
  seeds_csv,
  Simulation,
  sweep_csv,
  sweep_point,
  sweep_summary,
  variant,
} from '../dist/pkg/imlab.js';
import { english } from './core-english.mjs';

initSync({ module: readFileSync(new URL('../dist/pkg/imlab_bg.wasm', import.meta.url)) });

const STRINGS = 5_000;
const SEED = 20_240_611;
// Whole runs (inspect, seed_run, pin) only for scenarios this short, so the test stays quick.
const SHORT_STEPS = 1_000;
// Errors wasm-bindgen's glue throws when an instance was left mid-call by a trap: as bad as one.
const POISONED = /borrowed|null pointer passed to rust|recursive use of an object/i;

/** mulberry32: a small seeded generator, so every run tries the same inputs. */
function generator(seed) {
  let a = seed >>> 0;
  const next = () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
  const int = (lo, hi) => lo + Math.floor(next() * (hi - lo + 1));
  const pick = (list) => list[int(0, list.length - 1)];
  return { next, int, pick, chance: (p) => next() < p };
}

const rng = generator(SEED);
const FIELDS = describe('v=1&preset=step').info.fields;
const KEYS = ['v', 'preset', ...FIELDS.map((f) => f.key)];
const PRESETS = presets().map((p) => p.name);
const COLUMNS = columns();
const ODD_NUMBERS = [
  'NaN',
  'Infinity',
  '-Infinity',
  'inf',
  '1e309',
  '-1e309',
  '1e-320',
  '-0',
  '0x10',
  '1_000',
  '1,5',
  '١٢',
  '+5',
  '.5',
  '5.',
  'e5',
  '9'.repeat(400),
  `0.${'0'.repeat(400)}1`,
  '',
  ' ',
  '%20',
  '%',
  '%FF',
  '%00',
  'true',
  '[]',
  '{}',
  '1e',
  '--1',
];
const ODD_CHARS = [
  '&',
  '=',
  '%',
  '.',
  '-',
  'e',
  '+',
  '#',
  '?',
  ';',
  ' ',
  '\0',
  '\n',
  '\r',
  '\t',
  '\x7f',
  '\u2028',
  '\u202e',
  '\ufeff',
  '\ud800',
  '\udfff',
  'é',
  '😀',
  '\u0301',
  'ß',
  'İ',
  'ﬀ',
  '０',
];
const ODD_ARGS = [
  0,
  -1,
  1,
  0.5,
  NaN,
  Infinity,
  -Infinity,
  -0,
  2 ** 31,
  2 ** 32 - 1,
  2 ** 32,
  2 ** 53,
  1e308,
  -1e308,
  5e-324,
];

function number(f) {
  const x = f.min + rng.next() * (f.max - f.min);
  if (f.integer) return String(Math.round(x));
  return rng.chance(0.5) ? String(x) : x.toPrecision(rng.int(1, 6));
}

/** A scenario the codec should accept: a preset with a few fields set inside their ranges. */
function validScenario() {
  const parts = ['v=1', `preset=${rng.pick(PRESETS)}`];
  for (let i = rng.int(0, 5); i > 0; i--) {
    const f = rng.pick(FIELDS);
    parts.push(`${f.key}=${f.options.length ? rng.pick(f.options) : number(f)}`);
  }
  if (rng.chance(0.9)) parts.push(`duration=${rng.pick(['0.001', '0.005', '0.01', '0.02'])}`);
  return parts.join('&');
}

function mutated() {
  let s = validScenario();
  for (let i = rng.int(1, 6); i > 0; i--) {
    const at = rng.int(0, s.length);
    switch (rng.int(0, 6)) {
      case 0:
        s = s.slice(0, at) + rng.pick(ODD_CHARS) + s.slice(at);
        break;
      case 1:
        s = s.slice(0, at) + s.slice(at + rng.int(1, 5));
        break;
      case 2:
        s = s.slice(0, at) + rng.pick(ODD_NUMBERS) + s.slice(at + 1);
        break;
      case 3:
        s += `&${rng.pick(KEYS)}=${rng.pick(ODD_NUMBERS)}`;
        break;
      case 4:
        s = s.slice(0, at);
        break;
      case 5:
        s = s.split('&').reverse().join('&');
        break;
      default:
        s += s.slice(0, rng.int(0, s.length));
    }
  }
  return s;
}

function randomBytes() {
  const bytes = Uint8Array.from({ length: rng.int(0, 200) }, () => rng.int(0, 255));
  return new TextDecoder().decode(bytes);
}

function soup() {
  const pairs = [];
  for (let i = rng.int(1, 30); i > 0; i--) {
    const key = rng.chance(0.8) ? rng.pick(KEYS) : randomBytes().slice(0, 8);
    const value = rng.chance(0.5)
      ? rng.pick(ODD_NUMBERS)
      : rng.chance(0.5)
        ? String(rng.next() * 10 ** rng.int(-8, 8))
        : rng.pick([...PRESETS, 'rk4', 'ifoc', 'x']);
    pairs.push(rng.chance(0.9) ? `${key}=${value}` : key);
  }
  return pairs.join(rng.pick(['&', '&', '&', '&&', ';', '']));
}

function long() {
  const size = rng.int(5_000, 20_000);
  switch (rng.int(0, 3)) {
    case 0:
      return `v=1&preset=step&${'k1=1&'.repeat(size / 5)}`;
    case 1:
      return `v=1&preset=step&k1=${'9'.repeat(size)}`;
    case 2:
      return `v=1&preset=step&${'x'.repeat(size)}=1`;
    default:
      return rng.pick(ODD_CHARS).repeat(size);
  }
}

function controlled() {
  const s = validScenario();
  const at = rng.int(0, s.length);
  const noise = Array.from({ length: rng.int(1, 8) }, () =>
    String.fromCharCode(rng.chance(0.7) ? rng.int(0, 31) : rng.int(0xd800, 0xdfff)),
  ).join('');
  return s.slice(0, at) + noise + s.slice(at);
}

const KINDS = [validScenario, validScenario, mutated, mutated, randomBytes, soup, long, controlled];

function junk(depth = 0) {
  const point = () => ({
    freq: rng.pick([...ODD_ARGS, 10, 100]),
    gain: rng.next(),
    gain_db: rng.pick(ODD_ARGS),
    phase: rng.next(),
    gain_hat: 1,
    phase_hat: 0,
    saturated: rng.next(),
    failure: rng.pick([null, 'x', 5]),
  });
  const values = (length) => Array.from({ length }, () => rng.next());
  const run = () => {
    const n = rng.int(0, 5);
    return {
      result: {
        seed: rng.int(0, 9),
        tracking_rms: rng.next(),
        speed_estimate_error_rms: rng.pick(ODD_ARGS),
        tracking_peak: 1,
        failure: rng.pick([null, 'x']),
      },
      t: values(rng.chance(0.8) ? n : rng.int(0, 5)),
      error: values(n),
      estimate: values(rng.chance(0.8) ? n : rng.int(0, 5)),
    };
  };
  switch (rng.int(0, 9)) {
    case 0:
      return rng.pick([undefined, null, 0, NaN, '', 'x', true, Symbol.iterator]);
    case 1:
      return [];
    case 2:
      return Array.from({ length: rng.int(1, 50) }, point);
    case 3:
      return Array.from({ length: rng.int(1, 10) }, run);
    case 4:
      return Array.from({ length: rng.int(1, 10) }, () => run().result);
    case 5:
      return depth < 3 ? [junk(depth + 1), junk(depth + 1)] : {};
    case 6:
      return { length: 2 ** 32 - 1 };
    case 7:
      return Array.from({ length: rng.int(0, 5) }, () => rng.pick(ODD_ARGS));
    case 8: {
      let deep = [];
      for (let i = rng.int(10, 2_000); i > 0; i--) deep = [deep];
      return deep;
    }
    default:
      return Object.fromEntries(
        Array.from({ length: rng.int(0, 6) }, () => [
          rng.pick(['freq', 'gain', 'result', 't', 'seed', 'x']),
          junk(depth + 1),
        ]),
      );
  }
}

const counts = { strings: 0, calls: 0, successes: 0, cleanErrors: 0, traps: 0 };

/** Calls `fn(...args)`: a result or a clean error is counted; a trap fails the test with the arguments. */
function attempt(name, fn, ...args) {
  counts.calls++;
  try {
    const value = fn(...args);
    counts.successes++;
    return value;
  } catch (e) {
    // A refusal of the core is its message (its id and arguments), said here in English: an id
    // with no English message fails the test.
    const message = typeof e === 'object' && e !== null && 'id' in e && 'args' in e;
    const text = e instanceof Error ? e.message : message ? english(e) : String(e);
    if (e instanceof WebAssembly.RuntimeError || POISONED.test(text)) {
      counts.traps++;
      const shown = args.map((a) =>
        (typeof a === 'string'
          ? JSON.stringify(a)
          : (JSON.stringify(a, (_, v) => (typeof v === 'number' && !Number.isFinite(v) ? String(v) : v)) ?? String(a))
        ).slice(0, 300),
      );
      assert.fail(`${name} trapped (${e.name}: ${text}) on ${shown.join(', ')}`);
    }
    assert.ok(
      (typeof e === 'string' || e instanceof Error || message) && text.length > 0,
      `${name} threw ${String(e)} without a message`,
    );
    counts.cleanErrors++;
    return undefined;
  }
}

const oddArg = (...more) => rng.pick([...ODD_ARGS, ...more]);

/** Every exported function on `s` (and random further arguments); frees all it made. */
function exercise(s) {
  const info = attempt('describe', describe, s)?.info ?? undefined;
  attempt('recover', recover, s);
  attempt('variant', variant, s, rng.pick(KEYS), rng.chance(0.5) ? rng.pick(ODD_NUMBERS) : validScenario());
  attempt('variant', variant, validScenario(), rng.pick(KEYS), s);
  // Runs of the whole scenario only when it is short (or rejected before it runs).
  const short = info === undefined || info.steps <= SHORT_STEPS;
  if (short) {
    attempt('seed_run', seed_run, s, oddArg(rng.int(0, 1000)), rng.pick([0, 1, 7, 2 ** 32 - 1, -1, NaN]));
  }
  attempt(
    'sweep_point',
    sweep_point,
    s,
    rng.pick(['euler', 'ifocpi', 'constructor', '', 'rk4\u0000', 'é'.repeat(40)]),
    oddArg(50, 200),
    oddArg(0.02),
    rng.pick([0.01, 0.02, 0.05, -1, NaN, 0]),
    oddArg(0),
  );
  const plan = [
    oddArg(10),
    oddArg(1000),
    rng.pick([0, 1, 20, 200, 201, -1, 2.5, 2 ** 32 + 5, NaN]),
    oddArg(0.02),
    oddArg(0),
    oddArg(0.2),
  ];
  attempt('sweep_plan', sweep_plan, [...plan, rng.pick(['euler', 'rk4.ifocpi', 'nope', '', oddArg()])].join(','));

  const sim = attempt('new Simulation', (text) => new Simulation(text), s);
  const comparison = new Comparison();
  try {
    if (sim) {
      attempt('step', (n) => sim.step(n), rng.pick([0, 1, 10, 500, SHORT_STEPS, 2 ** 32 - 1, -1]));
      attempt(
        'csv_chunk',
        (start, count) => sim.csv_chunk(start, count),
        rng.pick([0, 1, 5, 2 ** 31, 2 ** 32 - 1, -1]),
        rng.pick([0, 1, 3, 100, 2 ** 32 - 1, -1]),
      );
      const names = Array.from({ length: rng.int(0, 4) }, () =>
        rng.chance(0.8) ? rng.pick(COLUMNS) : randomBytes().slice(0, 10),
      );
      const groups = rng.chance(0.9) ? [names, names.slice(1)] : rng.pick([null, 7, 'omega', [[1]], [names, 'x']]);
      attempt('keep_overview', (g, b) => sim.keep_overview(g, b), groups, rng.pick([0, 1, 7, 1000, 2 ** 32 - 1]));
      attempt(
        'view',
        (...a) => sim.view(...a),
        groups,
        oddArg(0),
        oddArg(0.01),
        rng.pick([0, 1, 2, 7, 1000, 2 ** 32 - 1, -1, NaN]),
      );
      attempt('report', () => sim.report());
      attempt('inspect', (t) => sim.inspect(t), oddArg(rng.next() * 0.02));
      attempt('metrics', () => sim.metrics());
      attempt('stability', () => sim.stability());
      attempt(
        'lyapunov_bound',
        (t) => sim.lyapunov_bound(t),
        Float64Array.from({ length: rng.int(0, 5) }, () => oddArg(rng.next())),
      );
      attempt('column', (name) => sim.column(name), rng.chance(0.7) ? rng.pick(COLUMNS) : s);
      attempt('keep_column', (name) => sim.keep_column(name), rng.chance(0.7) ? rng.pick(COLUMNS) : s);
      attempt('getters', () => [sim.done, sim.total, sim.rows, sim.finished, sim.scenario]);
    }
    const column = () => (rng.chance(0.8) ? rng.pick(COLUMNS) : randomBytes().slice(0, 10));
    if (short) attempt('pin', (text, c) => comparison.pin(text, c), s, column());
    attempt('pin', (text, c) => comparison.pin(text, c), 'v=1&preset=step&duration=0.002', column());
    if (sim) {
      attempt('legends', () => comparison.legends(sim));
      attempt(
        'overlay',
        (...a) => comparison.overlay(sim, ...a),
        rng.chance(0.7) ? rng.pick(COLUMNS) : s,
        oddArg(0),
        oddArg(0.01),
        rng.pick([0, 1, 100, 2 ** 32 - 1, -1]),
      );
    }
    attempt('unpin', (i) => comparison.unpin(i), rng.pick([0, 1, 5, -1, 2 ** 32 - 1, NaN]));
    attempt('scenarios', () => comparison.scenarios());
  } finally {
    sim?.free();
    comparison.free();
  }
  attempt('sweep_summary', sweep_summary, junk());
  attempt('sweep_csv', sweep_csv, junk());
  attempt('seeds_csv', seeds_csv, junk());
  attempt('seed_bands', seed_bands, junk());
}

test(`${STRINGS} generated inputs through every binding: clean errors, never a trap`, () => {
  const started = performance.now();
  for (let i = 0; i < STRINGS; i++) {
    exercise(rng.pick(KINDS)());
    counts.strings++;
  }
  const seconds = ((performance.now() - started) / 1000).toFixed(1);
  console.log(
    `fuzz: ${counts.strings} strings, ${counts.calls} calls: ${counts.successes} successes, ${counts.cleanErrors} clean errors, ${counts.traps} traps (${seconds} s)`,
  );
  assert.equal(counts.traps, 0);
  // The generators reach both sides of the codec.
  assert.ok(counts.successes > counts.calls / 10 && counts.cleanErrors > counts.calls / 10);
});

test('seed_bands refuses seed runs whose times and traces differ in length', () => {
  const result = { seed: 1, tracking_rms: 0, speed_estimate_error_rms: 0, tracking_peak: 0, failure: null };
  assert.throws(
    () => seed_bands([{ result, t: [], error: [0.1], estimate: [0.1] }]),
    (e) => !(e instanceof WebAssembly.RuntimeError),
  );
});
