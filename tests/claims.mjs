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
      const [header, ...lines] = execFileSync(CLI, ['run', '--every', String(every), run], { maxBuffer: 1 << 30 }).toString().trim().split('\n');
      const names = header.split(',');
      const rows = lines.map((l) => l.split(','));
      const columns = new Map();
      const column = (name) => {
        if (!columns.has(name)) {
          const i = names.indexOf(name);
          if (i < 0) throw new Error(`no column ${name}`);
          columns.set(name, Float64Array.from(rows, (r) => Number(r[i])));
        }
        return columns.get(name);
      };
      this.traces.set(run, { t: column('t'), column });
    }
    return this.traces.get(run);
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

/**
 * What is wrong with `text` against `spec` ({givens, checks}): every number of the text must be
 * a given (a setting of a run, written in `givens`) or the text of a check; every given and check
 * must be in the text; every check [written, tolerance, measure] must measure within tolerance of
 * the number written, and every [label, 'claim', test] must hold. Returns the problems, [] if none.
 */
export function checkText(text, spec, core) {
  const problems = [];
  const inText = new Set(numbersIn(text));
  const claimed = new Set([...spec.givens, ...spec.checks.map((c) => c[0])].flatMap(numbersIn));
  for (const n of inText) if (!claimed.has(n)) problems.push(`${n}: in the text, but neither a given nor checked`);
  for (const n of claimed) if (!inText.has(n)) problems.push(`${n}: checked or given, but not in the text`);
  for (const [written, tolerance, measure] of spec.checks) {
    if (tolerance === 'claim') {
      if (!measure(core)) problems.push(`claim "${written}" does not hold`);
      continue;
    }
    const value = measure(core);
    if (!(Math.abs(value - valueOf(written)) <= tolerance)) problems.push(`${written}: the run gives ${value} (tolerance ${tolerance})`);
  }
  return problems;
}
