// Checks of what the app's texts state against the native core: the numbers a text contains,
// and the figures of named runs (from `imlab metrics` and `imlab run`), each run computed once.
import { execFileSync } from 'node:child_process';

const CLI = new URL('../target/release/imlab', import.meta.url).pathname;

/** Most rows a trace keeps: longer runs keep every n-th sample (at most 0.2 ms apart for 8 s). */
const TRACE_ROWS = 40_000;

// A number as a text writes it: not part of a name (x3, k1, T0, a2), with an optional sign,
// thousands separators and exponent ("−25.4", "179,000", "1e7").
const NUMBER = /(?<![\p{L}\p{M}\p{N}_.,])[−-]?(?:\d{1,3}(?:,\d{3})+|\d+)(?:\.\d+)?(?:e[−-]?\d+)?/gu;

/** The numbers of `text`, as written. */
export function numbersIn(text) {
  return [...text.matchAll(NUMBER)].map((m) => m[0]);
}

/** The value of a number as written ("−2,480" → −2480). */
const valueOf = (written) => Number(written.replace(/−/g, '-').replace(/,/g, ''));

/** The native core, asked through the CLI; every run is computed once. */
export class Core {
  constructor() {
    this.metrics = new Map();
    this.traces = new Map();
  }

  /** Figure `name` of `imlab metrics run` (undefined when the run has none). */
  fig(run, name) {
    if (!this.metrics.has(run)) {
      let out;
      try {
        out = execFileSync(CLI, ['metrics', run], { stdio: ['ignore', 'pipe', 'pipe'] });
      } catch (e) {
        // A run that ran away prints its figures, then fails with its message.
        if (!/ran away/.test(e.stderr)) throw e;
        out = e.stdout;
      }
      const lines = out.toString().trim().split('\n').slice(1);
      this.metrics.set(run, Object.fromEntries(lines.map((l) => l.split(',')).map(([n, v]) => [n, Number(v)])));
    }
    return this.metrics.get(run)[name];
  }

  /** Whether `imlab metrics run` reports that the run ran away. */
  ranAway(run) {
    try {
      execFileSync(CLI, ['metrics', run], { stdio: ['ignore', 'ignore', 'pipe'] });
      return false;
    } catch (e) {
      return /ran away/.test(e.stderr);
    }
  }

  /** The recorded rows of `run`: {t, column(name) → Float64Array}. */
  trace(run) {
    if (!this.traces.has(run)) {
      const field = (key) => {
        const line = this.described(run).find((l) => l.startsWith(`${key} `));
        return Number(line.split('=')[1].trim().split(/\s+/)[0]);
      };
      const every = Math.max(1, Math.ceil(field('duration') / field('ts') / TRACE_ROWS));
      const [header, ...lines] = execFileSync(CLI, ['run', '--every', String(every), run], { maxBuffer: 1 << 30 })
        .toString()
        .trim()
        .split('\n');
      const names = header.split(',');
      const rows = lines.map((l) => l.split(','));
      const columns = new Map();
      const column = (name) => {
        if (!columns.has(name)) {
          const i = names.indexOf(name);
          if (i < 0) throw new Error(`no column ${name}`);
          columns.set(
            name,
            Float64Array.from(rows, (r) => Number(r[i])),
          );
        }
        return columns.get(name);
      };
      this.traces.set(run, { t: column('t'), column });
    }
    return this.traces.get(run);
  }

  /**
   * The rows of `imlab robust run --vary …`: one object a cell, by the CSV's column names
   * (numbers as numbers, an empty field as NaN, the cell's scenario as text).
   */
  robust(run, vary, seeds = '1..10') {
    const key = JSON.stringify([run, vary, seeds]);
    if (!this.maps) this.maps = new Map();
    if (!this.maps.has(key)) {
      const args = ['robust', run, ...[vary].flat().flatMap((v) => ['--vary', v]), '--seeds', seeds];
      const [, header, ...lines] = execFileSync(CLI, args, { stdio: ['ignore', 'pipe', 'ignore'] })
        .toString()
        .trim()
        .split('\n');
      const names = header.split(',');
      this.maps.set(
        key,
        lines.map((l) =>
          Object.fromEntries(
            l.split(',').map((v, i) => [names[i], names[i] === 'scenario' ? v : v === '' ? NaN : Number(v)]),
          ),
        ),
      );
    }
    return this.maps.get(key);
  }

  /** The mean frequency at which the stator current vector of `run` turns from time t0 on (Hz). */
  statorFrequency(run, t0) {
    const tr = this.trace(run);
    const [a, b] = [tr.column('i_sa'), tr.column('i_sb')];
    let [turned, prev, first] = [0, null, -1];
    tr.t.forEach((t, i) => {
      if (t < t0) return;
      const angle = Math.atan2(b[i], a[i]);
      if (prev !== null) turned += ((angle - prev + 3 * Math.PI) % (2 * Math.PI)) - Math.PI;
      else first = i;
      prev = angle;
    });
    return turned / (2 * Math.PI * (tr.t.at(-1) - tr.t[first]));
  }

  described(run) {
    return execFileSync(CLI, ['describe', run]).toString().split('\n');
  }

  /** Column `name` of `run` at the recorded sample nearest to time `t` (s). */
  at(run, name, t) {
    const tr = this.trace(run);
    let best = 0;
    tr.t.forEach((ti, i) => {
      if (Math.abs(ti - t) < Math.abs(tr.t[best] - t)) best = i;
    });
    return tr.column(name)[best];
  }

  /** The samples of column `name` of `run` with t0 ≤ t ≤ t1: {rms, mean, min, max, maxAbs}. */
  stat(run, name, t0, t1) {
    const tr = this.trace(run);
    const slack = 0.5 * (tr.t[1] - tr.t[0]);
    const v = [...tr.column(name)].filter((_, i) => tr.t[i] >= t0 - slack && tr.t[i] <= t1 + slack);
    return {
      rms: Math.sqrt(v.reduce((s, x) => s + x * x, 0) / v.length),
      mean: v.reduce((s, x) => s + x, 0) / v.length,
      min: Math.min(...v),
      max: Math.max(...v),
      maxAbs: Math.max(...v.map(Math.abs)),
    };
  }

  /** The largest stator-current magnitude |i_s| of `run` from time t0 on (A). */
  peakCurrent(run, t0) {
    const tr = this.trace(run);
    const [a, b] = [tr.column('i_sa'), tr.column('i_sb')];
    let peak = 0;
    tr.t.forEach((t, i) => {
      if (t >= t0) peak = Math.max(peak, Math.hypot(a[i], b[i]));
    });
    return peak;
  }

  /**
   * Time from `from` (s) until |ω − ω_d| enters `band` (rad/s) for good: 0 when it never leaves
   * the band after `from`, Infinity when it is outside at the end.
   */
  recovery(run, from, band) {
    const tr = this.trace(run);
    const err = tr.column('omega_err');
    let last = -1;
    tr.t.forEach((t, i) => {
      if (t >= from && Math.abs(err[i]) > band) last = i;
    });
    if (last === tr.t.length - 1) return Infinity;
    return last < 0 ? 0 : tr.t[last + 1] - from;
  }

  /** For each recorded sample of `run`, whether the limit changed its voltage command. */
  clipped(run) {
    const tr = this.trace(run);
    const [ua, ub, ca, cb] = ['u_a', 'u_b', 'u_a_cmd', 'u_b_cmd'].map((c) => tr.column(c));
    return { t: tr.t, at: (i) => ua[i] !== ca[i] || ub[i] !== cb[i] };
  }

  /** The share of all recorded samples whose voltage command the limit changed. */
  clippedShare(run) {
    const { t, at } = this.clipped(run);
    return t.filter((_, i) => at(i)).length / t.length;
  }

  /** The time of the first sample whose voltage command the limit changed (s), or Infinity. */
  firstSaturated(run) {
    const { t, at } = this.clipped(run);
    const i = t.findIndex((_, k) => at(k));
    return i < 0 ? Infinity : t[i];
  }

  /** The time of the last sample whose voltage command the limit changed (s), or −Infinity. */
  lastSaturated(run) {
    const { t, at } = this.clipped(run);
    const i = t.findLastIndex((_, k) => at(k));
    return i < 0 ? -Infinity : t[i];
  }
}

/** The seeds a statement that the noise moves is checked over. */
export const SEEDS = [1, 2, 3, 4, 5, 6, 7, 8, 9, 10];

/** The default sample of noise draws, as the measurements tables take it (seeds 1..30). */
export const SEEDS_30 = Array.from({ length: 30 }, (_, i) => i + 1);

/** `run` with noise seed `seed`. */
export const withSeed = (run, seed) => `${run}&seed=${seed}`;

// Words that make a sentence causal: each occurrence must lie inside the phrase of a 'cause'
// check, which removes the named cause and shows the effect go (or stay, for "not because").
const CAUSAL = /\b(?:because|set by|comes? from|caused by|due to|is why|that is why)\b/gu;

/** A phrase's text as it stands in the text (brackets removed) and its bracketed numbers. */
function parsePhrase(phrase) {
  const measured = [...phrase.matchAll(/\[([^\]]*)\]/g)].map((m) => m[1]);
  return { plain: phrase.replace(/\[([^\]]*)\]/g, '$1'), measured };
}

/** Every index at which `needle` starts in `text`. */
function occurrences(text, needle) {
  const out = [];
  for (let i = text.indexOf(needle); i >= 0; i = text.indexOf(needle, i + 1)) out.push(i);
  return out;
}

// Each check's measured result, computed once: the swap test reads a text many times.
const measuredOf = new WeakMap();

/** What check `check` measures: a value, a [least, largest] pair over seeds, or a boolean. */
function measure(check, core) {
  if (!measuredOf.has(check)) {
    const [, kind, fn] = check;
    let result;
    if (typeof kind === 'object' && kind.seeds) {
      const values = kind.seeds.map((seed) => fn(core, seed));
      result = kind.range !== undefined ? [Math.min(...values), Math.max(...values)] : values;
    } else {
      result = fn(core);
    }
    measuredOf.set(check, result);
  }
  return measuredOf.get(check);
}

/**
 * What is wrong with `text` against `spec` ({givens, checks}). Returns the problems, [] if none.
 *
 * Every phrase is written as it stands in the text, so that a check is tied to its neighbouring
 * words: moving its number to another place fails. A given is a setting of a run ('at 0.3 s');
 * a check is [phrase, kind, measure] with the numbers it measures in brackets
 * ('[5.0] rad/s low at 0.3 s'), and kind one of
 * - a number: the tolerance of the one bracketed number against measure(core);
 * - {tol, seeds}: the same on every seed of `seeds` (a figure the noise does not move),
 *   measure(core, seed);
 * - {range: tol, seeds}: two bracketed numbers, the least and the largest of measure(core, seed)
 *   over the seeds (a figure the noise moves, stated as its range), in either order;
 * - 'claim': measure(core) must be true;
 * - 'cause': a claim that removes the cause the phrase names (and shows the effect go, or stay
 *   for "not because"); every causal word of the text must be inside such a phrase.
 * Every phrase must be in the text, and every number of the text inside a given or a check.
 */
export function checkText(text, spec, core) {
  const problems = [];
  const covered = new Array(text.length).fill(false);
  const cover = (plain, what) => {
    const at = occurrences(text, plain);
    if (!at.length) problems.push(`${what} "${plain}": not in the text`);
    for (const i of at) covered.fill(true, i, i + plain.length);
    return at;
  };
  for (const given of spec.givens) cover(given, 'given');
  const causal = new Array(text.length).fill(false);
  for (const check of spec.checks) {
    const [phrase, kind] = check;
    const { plain, measured } = parsePhrase(phrase);
    const at = cover(plain, 'check');
    if (kind === 'cause') for (const i of at) causal.fill(true, i, i + plain.length);
    if (!at.length) continue;
    const result = measure(check, core);
    if (kind === 'claim' || kind === 'cause') {
      if (!result) problems.push(`${kind} "${plain}" does not hold`);
    } else if (typeof kind === 'number') {
      if (measured.length !== 1) problems.push(`"${phrase}": a value check brackets one number`);
      else if (!(Math.abs(result - valueOf(measured[0])) <= kind))
        problems.push(`${measured[0]} in "${plain}": the run gives ${result} (tolerance ${kind})`);
    } else if (kind.range !== undefined) {
      const [lo, hi] = measured.map(valueOf).sort((a, b) => a - b);
      if (measured.length !== 2) problems.push(`"${phrase}": a range brackets two numbers`);
      else if (!(Math.abs(result[0] - lo) <= kind.range && Math.abs(result[1] - hi) <= kind.range)) {
        problems.push(
          `${measured.join(' to ')} in "${plain}": seeds ${kind.seeds[0]}–${kind.seeds.at(-1)} give ${result[0]} to ${result[1]} (tolerance ${kind.range})`,
        );
      }
    } else {
      if (measured.length !== 1) problems.push(`"${phrase}": a value check brackets one number`);
      const bad = kind.seeds.filter((_, i) => !(Math.abs(result[i] - valueOf(measured[0])) <= kind.tol));
      if (bad.length)
        problems.push(
          `${measured[0]} in "${plain}": not within ${kind.tol} on seeds ${bad.join(', ')} (${result.map((v) => v.toPrecision(4)).join(', ')})`,
        );
    }
  }
  for (const m of text.matchAll(NUMBER)) {
    if (!covered.slice(m.index, m.index + m[0].length).every(Boolean))
      problems.push(`${m[0]} at "${context(text, m.index)}": in the text, but neither a given nor checked`);
  }
  for (const m of text.matchAll(CAUSAL)) {
    if (!causal[m.index])
      problems.push(`"${m[0]}" at "${context(text, m.index)}": a causal sentence with no check that removes its cause`);
  }
  return problems;
}

/** A few words of `text` around index `i`. */
function context(text, i) {
  return text.slice(Math.max(0, i - 30), i + 30).replace(/\s+/g, ' ');
}

/**
 * The swaps of two numbers of `text` (different as written) that `checkText` does not notice:
 * each is [first, second, the context of the first]. A text whose checks are tied to their
 * places gives none.
 */
export function unnoticedSwaps(text, spec, core) {
  const found = [...text.matchAll(NUMBER)];
  const out = [];
  for (let a = 0; a < found.length; a++) {
    for (let b = a + 1; b < found.length; b++) {
      const [x, y] = [found[a], found[b]];
      if (x[0] === y[0]) continue;
      const swapped =
        text.slice(0, x.index) +
        y[0] +
        text.slice(x.index + x[0].length, y.index) +
        x[0] +
        text.slice(y.index + y[0].length);
      if (!checkText(swapped, spec, core).length) out.push([x[0], y[0], context(text, x.index)]);
    }
  }
  return out;
}
