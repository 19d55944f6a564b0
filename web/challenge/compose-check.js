// The check of a composed challenge, for the lecturer: before the link goes out, the core lists
// designs within the allowed ranges (the base first, then those that change the fewest fields;
// the full grid when it fits), each is run and judged as a student's submission would be, in a
// pool of workers with progress and Cancel, and the form says whether one passes, or how close
// the closest came. A check takes at most RUN_BUDGET runs.
import { el } from '../ui/dom.js';
import { Pool } from '../client/pool.js';
import { formatValue } from './checklist.js';
import { t } from '../l10n/l10n.js';
import { integer } from '../analysis/digits.js';

/**
 * @import * as P from '../worker/protocol.js'
 * @import { RunClient } from '../client/run-client.js'
 * @import { Criterion, Verdict } from './checklist.js'
 * @import { Challenge, Need } from './challenge.js'
 */

/**
 * A design ([field, value] pairs, none for the base), the measures of a run, a design tried (its
 * runs' measures and the core's verdict on them), and a check under way.
 * @typedef {[string, string][]} Design
 * @typedef {P.Jobs['challenge-run']['result']} Measures
 * @typedef {{tries: Design, runs: Measures[], verdict: Verdict}} Tried
 * @typedef {{cancelled: boolean}} Check
 */

/** The most runs a check takes: as many designs as fit, each with its nominal run and variants. */
export const RUN_BUDGET = 300;

/**
 * A design in words: `k1=600, k2=1200`, or the base.
 * @param {Design} tries
 */
const designText = (tries) =>
  tries.length ? tries.map(([field, value]) => `${field}=${value}`).join(', ') : t('compose-check-base-design');

/**
 * The criteria a verdict fails, in words: `current_peak: 3.21 A vs ≤ 0.1 A`.
 * @param {Verdict} verdict
 */
function failures(verdict) {
  return verdict.criteria
    .filter((/** @type {Criterion} */ c) => !c.pass)
    .map((/** @type {Criterion} */ c) => {
      const reason = c.reason ? c.reason : '';
      if (c.value === null) return t('compose-check-unmeasured', { figure: c.figure, reason });
      const args = { figure: c.figure, value: formatValue(c.value, c.unit), bound: c.bound };
      return t(c.settled ? 'compose-check-failure' : 'compose-check-failure-changing', args);
    })
    .join('; ');
}

/**
 * How far failing criterion `c` (verdict) of `need` is beyond its bound, relative to the bound
 * (for the mean NIS, to its band's width on `run`, the measures of the run judged).
 * @param {Criterion} c
 * @param {Need} need
 * @param {Measures | undefined} run
 * @returns {number}
 */
function excess(c, need, run) {
  if (c.value === null || !Number.isFinite(c.value)) return Infinity;
  /**
   * `over` relative to `scale` (a bound of zero counts as one), none below zero.
   * @param {number} over
   * @param {number} scale
   */
  const rel = (over, scale) => Math.max(0, over / (Math.abs(scale) || 1));
  // Every op but 'band' has a bound (the core's `Op`), and only they read it.
  const bound = /** @type {number} */ (need.bound);
  if (need.op === 'max') return rel(c.value - bound, bound);
  if (need.op === 'min') return rel(bound - c.value, bound);
  if (need.op === 'abs') return rel(Math.abs(c.value) - bound, bound);
  /**
   * The value of the run's figure `name`, if it has one.
   * @param {string} name
   * @returns {number | undefined}
   */
  const band = (name) => run?.figures.find((/** @type {Measures['figures'][number]} */ f) => f.name === name)?.value;
  const [lo, hi] = [band('mean_nis_low'), band('mean_nis_high')];
  return lo === undefined || hi === undefined ? 1 : rel(Math.max(lo - c.value, c.value - hi), hi - lo);
}

/**
 * How far a tried design is from passing, to find the closest: the criteria it fails, then the
 * largest relative excess among them.
 * @param {Tried} tried
 * @param {Challenge} desc
 * @param {string[]} labels
 * @returns {[number, number]}
 */
function shortfall(tried, desc, labels) {
  /** @type {Criterion[]} */
  const failed = tried.verdict.criteria.filter((/** @type {Criterion} */ c) => !c.pass);
  // The verdict has a criterion for each of the challenge's needs, on the same figure.
  const worst = failed.map((c) =>
    excess(
      c,
      /** @type {Need} */ (desc.need.find((/** @type {Need} */ n) => n.figure === c.figure)),
      tried.runs[labels.indexOf(c.run)],
    ),
  );
  return [failed.length, Math.max(0, ...worst)];
}

/**
 * The first of `tried` with the smallest shortfall (null when none was tried).
 * @param {Tried[]} tried
 * @param {Challenge} desc
 * @param {string[]} labels
 */
function closest(tried, desc, labels) {
  /** @type {Tried | null} */
  let best = null;
  /** @type {[number, number] | null} the shortfall of `best` */
  let bestKey = null;
  for (const t of tried) {
    const key = shortfall(t, desc, labels);
    if (!bestKey || key[0] < bestKey[0] || (key[0] === bestKey[0] && key[1] < bestKey[1])) {
      best = t;
      bestKey = key;
    }
  }
  return best;
}

/**
 * What a finished check found, in words: the verdict line and the details (the base, the bound).
 * @param {{desc: Challenge, labels: string[], tried: Tried[], runs: number}} found
 */
function findings({ desc, labels, tried, runs }) {
  const m = tried.length;
  const passing = tried.filter((d) => d.verdict.pass);
  const base = tried.find((d) => d.tries.length === 0);
  const baseLine = !base
    ? []
    : base.verdict.pass
      ? [t('compose-check-base-passes')]
      : [t('compose-check-base-fails', { failures: failures(base.verdict) })];
  const bound = t('compose-check-tried', { designs: integer(m), runs: integer(runs), budget: integer(RUN_BUDGET) });
  // The details are sentences, one after the other.
  const details = [...baseLine, bound].join(' ');
  if (passing.length) {
    const shown = passing.find((d) => d.tries.length) ?? passing[0];
    return {
      solvable: true,
      line: t('compose-check-solvable', {
        design: designText(shown.tries),
        passing: integer(passing.length),
        tried: integer(m),
      }),
      details,
    };
  }
  // A check tries the base at least, whose submission runs.
  const near = /** @type {Tried} */ (closest(tried, desc, labels));
  return {
    solvable: false,
    line: t('compose-check-unsolved', {
      tried: integer(m),
      design: designText(near.tries),
      failures: failures(near.verdict),
    }),
    details,
  };
}

/**
 * The check's part of the compose form: `box` to show beside the link, `check(text)` to check the
 * challenge `text` (a newer check supersedes one under way) and `stop()` to cancel it.
 * `client` is the page's worker.
 * @param {{client: RunClient}} page
 */
export function createCheck({ client }) {
  const line = el('p', { id: 'compose-check', className: 'verdict', role: 'status' });
  const details = el('p', { id: 'compose-check-details', className: 'hint' });
  const progress = /** @type {HTMLProgressElement} */ (
    el('progress', { id: 'compose-check-progress', max: 1, value: 0, hidden: true })
  );
  progress.setAttribute('aria-label', t('compose-check-progress.aria-label'));
  const cancel = /** @type {HTMLButtonElement} */ (
    el('button', {
      type: 'button',
      id: 'compose-check-cancel',
      textContent: t('compose-check-cancel'),
      disabled: true,
    })
  );
  /** @type {HTMLElement} */
  const box = el('div', { className: 'compose-check' }, [
    line,
    el('div', { className: 'buttons' }, [progress, cancel]),
    details,
  ]);
  const state = document.body.dataset;
  /** @type {Pool | null} */
  let pool = null;
  /** @type {Check | null} the check under way */
  let current = null;

  function stop() {
    if (current) current.cancelled = true;
    pool?.cancel();
  }
  cancel.addEventListener('click', stop);

  /**
   * Runs `jobs` in the pool, unless check `me` was cancelled; `onDone(count)` as each ends.
   * @template {keyof P.Jobs} K
   * @param {Check} me
   * @param {({kind: K} & P.Jobs[K]['req'])[]} jobs
   * @param {(count: number) => void} [onDone]
   */
  async function inPool(me, jobs, onDone) {
    if (me.cancelled) throw new Error('cancelled');
    pool ??= new Pool(1);
    pool.size = Math.max(1, Math.min(jobs.length, 4, navigator.hardwareConcurrency || 2));
    const results = await pool.run(jobs, onDone);
    if (me.cancelled) throw new Error('cancelled');
    return results;
  }

  /**
   * Check `me` of challenge `text`: its designs, each one's runs measured, and their verdicts.
   * @param {Check} me
   * @param {string} text
   */
  async function search(me, text) {
    const desc = await client.job('challenge', { text });
    const labels = ['nominal', ...desc.variants];
    const max = Math.max(1, Math.floor(RUN_BUDGET / labels.length));
    const designs = await client.job('challenge-designs', { text, max });
    const subs = await inPool(
      me,
      designs.map((tries) => ({ kind: /** @type {const} */ ('challenge-tries'), text, tries })),
    );
    const scenarios = subs.flatMap((s) => s.scenarios);
    const tell = (/** @type {number} */ done) => {
      progress.value = done / scenarios.length;
      line.textContent = t('compose-check-running', {
        done: integer(done),
        runs: integer(scenarios.length),
        designs: integer(designs.length),
      });
    };
    tell(0);
    const measures = await inPool(
      me,
      scenarios.map((scenario) => ({ kind: /** @type {const} */ ('challenge-run'), scenario })),
      tell,
    );
    let at = 0;
    /** @type {Omit<Tried, 'verdict'>[]} */
    const ran = designs
      .map((tries, i) => ({ tries, runs: measures.slice(at, (at += subs[i].scenarios.length)) }))
      .filter((t) => t.runs.length > 0);
    const verdicts = await inPool(
      me,
      ran.map((t) => ({ kind: /** @type {const} */ ('challenge-judge'), text, runs: t.runs })),
    );
    /** @type {Tried[]} */
    const tried = ran.map((t, i) => ({ ...t, verdict: verdicts[i] }));
    return { desc, labels, tried, runs: scenarios.length };
  }

  /**
   * Checks challenge `text`, ending the check under way.
   * @param {string} text
   */
  async function check(text) {
    stop();
    const me = { cancelled: false };
    current = me;
    state.composeCheck = 'running';
    line.textContent = t('compose-check-starting');
    details.textContent = '';
    progress.hidden = false;
    progress.value = 0;
    cancel.disabled = false;
    try {
      const found = findings(await search(me, text));
      if (current !== me) return;
      line.textContent = found.line;
      details.textContent = found.details;
      state.composeCheck = found.solvable ? 'solvable' : 'unsolved';
    } catch (e) {
      if (current !== me) return;
      const cancelled = /** @type {Error} */ (e).message === 'cancelled';
      line.textContent = cancelled
        ? t('compose-check-cancelled')
        : t('compose-check-failed', { reason: /** @type {Error} */ (e).message });
      state.composeCheck = cancelled ? 'cancelled' : 'failed';
    } finally {
      if (current === me) {
        progress.hidden = true;
        cancel.disabled = true;
      }
    }
  }

  return { box, check, stop };
}
