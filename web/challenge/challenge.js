// The challenge a link opens, for the student: the task, where it comes from (origin.js), the knobs
// it allows (the other settings locked), and the checklist of its criteria, judged by the core after every run on the nominal
// run and on each robustness variant (run in a pool of workers, with progress and Cancel). The
// address then holds the student's submission link. The built-in challenges are listed in the
// Lessons tab.
import { $, ui } from '../ui/page.js';
import { fieldValue } from '../ui/scenario.js';
import { Pool } from '../client/pool.js';
import { challengeFromUrl, holdAddress, scenarioFromUrl } from '../ui/url.js';
import { el } from '../ui/dom.js';
import { panelParts, showVerdict } from './checklist.js';
import { copyToForm, knob } from './knobs.js';
import { header, originOf } from './origin.js';
import { loadRest, t } from '../l10n/l10n.js';
import { integer } from '../analysis/digits.js';
import { briefText } from './brief.js';

/** @import * as P from '../worker/protocol.js' */
/** @import { RunClient } from '../client/run-client.js' */
/** @import { Control, Allowed } from './knobs.js' */
/** @import { Submission } from './checklist.js' */
/** @import { Origin } from './origin.js' */

/**
 * The core's description of a challenge, one of its criteria, the challenge in the address, and
 * the page's state as the challenge reads it: the scenario in the form (null until described), the last run.
 * @typedef {P.Jobs['challenge']['result']} Challenge
 * @typedef {Challenge['need'][number]} Need
 * @typedef {NonNullable<ReturnType<typeof challengeFromUrl>>} Link
 * @typedef {{info: P.Info | null, runId: number, running: boolean, ranScenario: string | null}} PageState
 * @typedef {ReturnType<typeof import('../ui/stale.js').createStale>} Stale
 */

/** The page's state attributes, which the tests wait on. */
const body = () => document.body.dataset;

/**
 * The student's side of a challenge; `client` is the page's worker, `relayout()` sizes the plots
 * to the room the panel leaves them, `stale` marks a verdict while the settings are not the ones it
 * checked.
 */
export class ChallengePanel {
  /** @param {{client: RunClient, state: PageState, relayout: () => void, stale: Stale}} page */
  constructor({ client, state, relayout, stale }) {
    this.client = client;
    this.state = state;
    this.relayout = relayout;
    this.panel = $('challenge-panel');
    this.link = challengeFromUrl();
    /** @type {Challenge | null} the core's description of the open challenge */
    this.desc = null;
    /** @type {Origin} where the open challenge comes from, as its header says */
    this.origin = 'unknown';
    /** @type {string | null} why the link's submission was refused, until the student runs their own */
    this.refused = null;
    this.grading = 0; // checks started: a newer one supersedes the one under way
    /** @type {Pool | null} workers for the variants, started at the first check that has some */
    this.pool = null;
    /** @type {Map<string, Control>} field → the panel's control */
    this.knobs = new Map();
    this.parts = panelParts();
    // The submission link a stale verdict's panel copies is the checked one's, which it names.
    this.shown = stale.add({
      name: 'challenge',
      before: this.parts.verdict,
      shows: [this.parts.verdict, this.parts.checklist],
    });
  }

  /** Whether a challenge is open. */
  active() {
    return this.link !== null && this.desc !== null;
  }

  /** Shows the error `text` in the panel (empty clears it). @param {string} text */
  fail(text) {
    this.parts.alert.textContent = text;
    this.parts.alert.hidden = !text;
  }

  /**
   * Opens the challenge in the address, if any: shows its task and resolves with the scenario of
   * its nominal run (the link's settings, or the base's when they are refused). Without a
   * challenge (or with one the core rejects) it resolves with the address's scenario.
   */
  async open() {
    if (!this.link) return scenarioFromUrl();
    try {
      return await this.openLink();
    } catch (e) {
      this.fail(t('challenge-open-failed', { reason: /** @type {Error} */ (e).message }));
      body().challenge = 'failed';
      this.desc = null;
      return scenarioFromUrl();
    }
  }

  async openLink() {
    // The panel says the rest of the page's messages.
    await loadRest();
    const { client } = this;
    const link = /** @type {Link} */ (this.link);
    document.body.classList.add('with-challenge');
    this.panel.hidden = false;
    body().challenge = 'loading';
    this.panel.replaceChildren(el('h2', { textContent: t('challenge-heading') }), this.parts.alert);
    try {
      this.desc = await client.job('challenge', { text: link.challenge });
    } catch (e) {
      this.fail(t('challenge-link-rejected', { reason: /** @type {Error} */ (e).message }));
      body().challenge = 'malformed';
      return scenarioFromUrl();
    }
    const text = this.desc.encoded;
    const origin = originOf(client, text);
    let sub = await client.job('challenge-submission', { text, submission: link.submission ?? text });
    if (sub.kind !== 'ok') {
      this.refused =
        sub.kind === 'another'
          ? t('challenge-submission-another')
          : t(sub.kind === 'refused' ? 'challenge-submission-refused' : 'challenge-submission-rejected', {
              reason: sub.message ?? '',
            });
      sub = await client.job('challenge-submission', { text, submission: text });
    }
    holdAddress(this.refused ? location.search.slice(1) : sub.encoded);
    this.origin = await origin;
    this.render();
    if (this.refused) {
      this.fail(this.refused);
      body().challenge = 'refused';
    } else body().challenge = 'open';
    return sub.scenarios[0];
  }

  render() {
    const { parts, knobs } = this;
    const desc = /** @type {Challenge} */ (this.desc);
    const run = el('button', { type: 'button', id: 'challenge-run', textContent: t('challenge-run') });
    run.addEventListener('click', () => {
      for (const [field, control] of knobs) copyToForm(field, control);
      ui.run.click();
    });
    const knobBox = el('div', { className: 'knobs challenge-knobs' });
    for (const a of desc.allow) knobBox.append(knob(a, knobs));
    parts.copy.addEventListener('click', () => this.copySubmission());
    parts.cancel.addEventListener('click', () => this.pool?.cancel());
    this.panel.replaceChildren(
      ...header(desc, this.origin),
      parts.alert,
      el('h3', { textContent: t('challenge-settings') }),
      el('p', {
        className: 'hint',
        textContent: t('challenge-settings-hint', {
          fields: desc.allow.map((/** @type {Allowed} */ a) => a.field).join(', '),
        }),
      }),
      knobBox,
      el('div', { className: 'buttons' }, [run, parts.cancel]),
      parts.progress,
      el('h3', { textContent: t('challenge-checklist') }),
      parts.verdict,
      parts.checklist,
      el('div', { className: 'buttons' }, [parts.copy]),
      parts.copied,
      el('details', { className: 'brief', open: true }, [
        el('summary', { textContent: t('challenge-task') }),
        el('div', { className: 'brief-text', textContent: briefText(desc.task).trimEnd() }),
      ]),
    );
    this.relayout();
    parts.verdict.textContent = t('challenge-verdict-pending');
    parts.checklist.replaceChildren(
      ...desc.need.map((/** @type {Need} */ n) =>
        el('li', { textContent: t('challenge-need-pending', { label: n.label, figure: n.figure }) }),
      ),
    );
  }

  /**
   * Only the allowed fields stay editable, in the settings and the walkthrough's knobs: after each
   * description, and whenever more of their fields are built (the panel's own knobs are left as
   * they are: one may hold an edit the form has not described yet).
   */
  lock() {
    if (!this.desc) return;
    ui.preset.disabled = true;
    const allowed = new Set(this.desc.allow.map((/** @type {Allowed} */ a) => a.field));
    const controls = /** @type {NodeListOf<HTMLInputElement | HTMLSelectElement>} */ (
      document.querySelectorAll(
        '#settings input, #settings select, #walkthrough .knobs input, #walkthrough .knobs select',
      )
    );
    for (const c of controls) c.disabled = !allowed.has(c.name);
  }

  /**
   * After each description of the form: the fields are locked, and the panel follows the form.
   * @param {P.Info} info
   */
  described(info) {
    if (!this.desc) return;
    this.lock();
    for (const [field, control] of this.knobs) {
      if (control !== document.activeElement) control.value = fieldValue(info, field) ?? '';
    }
  }

  /**
   * The student's values of the allowed fields in `info` that differ from the base's.
   * @param {P.Info} info
   * @returns {[string, string][]}
   */
  tries(info) {
    const desc = /** @type {Challenge} */ (this.desc);
    return desc.allow.flatMap((a) => {
      const v = fieldValue(info, a.field);
      return v !== null && v !== a.value ? [/** @type {[string, string]} */ ([a.field, v])] : [];
    });
  }

  /**
   * Whether the scenario `info` may run: `true` at once with no challenge open; with one, a
   * promise of it, as a valid answer (the address then names the run on screen); a value outside
   * the allowed range is refused before any run, and said.
   * @param {P.Info} info
   * @returns {true | Promise<boolean>}
   */
  mayRun(info) {
    return this.desc ? this.answers(info) : true;
  }

  /** Whether `info` is a valid answer to the open challenge; a refusal is said. @param {P.Info} info */
  async answers(info) {
    const desc = /** @type {Challenge} */ (this.desc);
    const sub = await this.client.job('challenge-tries', { text: desc.encoded, tries: this.tries(info) });
    if (sub.kind === 'ok') return true;
    // A check under way is of the settings before this edit: it ends here.
    this.grading++;
    this.pool?.cancel();
    this.parts.progress.hidden = true;
    this.parts.cancel.disabled = true;
    this.showRefusal(sub, false);
    return false;
  }

  /** The description of the scenario run last (the form's, unless it has been edited since). */
  ranInfo() {
    const { state } = this;
    // Both are set once a run has started, which a check follows.
    const info = /** @type {P.Info} */ (state.info);
    return info.encoded === state.ranScenario ? info : this.client.describe(/** @type {string} */ (state.ranScenario));
  }

  /**
   * Checks the run that just ended: the student's settings as a submission, the measures of the
   * nominal run (this run's, when it is the one the challenge asks for) and of each variant, and
   * the core's verdict on them.
   */
  async check() {
    if (!this.desc) return;
    const me = ++this.grading;
    const runId = this.state.runId;
    this.shown.forget();
    const { verdict, progress, cancel } = this.parts;
    if (this.refused && runId === 1) {
      verdict.textContent = t('challenge-verdict-link-refused');
      body().challengeChecked = String(runId);
      return;
    }
    this.refused = null;
    this.fail('');
    this.pool?.cancel();
    body().challenge = 'checking';
    try {
      await this.grade(me, runId);
    } catch (e) {
      if (me !== this.grading) return;
      const cancelled = /** @type {Error} */ (e).message === 'cancelled';
      verdict.textContent = cancelled
        ? t('challenge-verdict-cancelled')
        : t('challenge-verdict-failed', { reason: /** @type {Error} */ (e).message });
      body().challenge = cancelled ? 'cancelled' : 'failed';
    } finally {
      if (me === this.grading) {
        progress.hidden = true;
        cancel.disabled = true;
        body().challengeChecked = String(runId);
      }
    }
  }

  /**
   * The check `me` of run `runId`: its submission, its runs measured, and the core's verdict.
   * @param {number} me
   * @param {number} runId
   */
  async grade(me, runId) {
    const { client, state, parts } = this;
    const desc = /** @type {Challenge} */ (this.desc);
    const checked = /** @type {string} */ (state.ranScenario);
    const sub = await client.job('challenge-tries', { text: desc.encoded, tries: this.tries(await this.ranInfo()) });
    if (me !== this.grading) return;
    if (sub.kind !== 'ok') {
      this.showRefusal(sub, true);
      return;
    }
    const held = sub.scenarios[0] === state.ranScenario ? await client.measure(runId) : null;
    body().challengeNominal = held ? 'page' : 'pool';
    const measured = await this.measureRuns(held ? sub.scenarios.slice(1) : sub.scenarios, held !== null);
    if (me !== this.grading) return;
    const result = await client.job('challenge-judge', {
      text: desc.encoded,
      runs: held ? [held, ...measured] : measured,
    });
    if (me !== this.grading) return;
    showVerdict(parts, result, sub);
    this.shown.ran(checked);
    // Further sentences on what was graded follow the verdict's.
    if (desc.edited_from) parts.verdict.append(` ${t('challenge-verdict-edited', { name: desc.edited_from })}`);
    if (!held) parts.verdict.append(` ${t('challenge-verdict-rerun')}`);
    holdAddress(sub.encoded);
    this.copyable(true);
    body().challenge = result.pass ? 'pass' : 'fail';
  }

  /**
   * Measures `scenarios` in the pool with progress (the nominal run is the first of them unless
   * the page `held` it); rejects with 'cancelled' on Cancel.
   * @param {string[]} scenarios
   * @param {boolean} held
   */
  async measureRuns(scenarios, held) {
    if (!scenarios.length) return [];
    const { progress, cancel, verdict } = this.parts;
    this.pool ??= new Pool(1);
    this.pool.size = Math.max(1, Math.min(scenarios.length, 4, navigator.hardwareConcurrency || 2));
    progress.hidden = false;
    progress.value = 0;
    cancel.disabled = false;
    const total = scenarios.length + (held ? 1 : 0);
    const me = this.grading;
    const tell = (/** @type {number} */ done) => {
      if (me !== this.grading) return;
      progress.value = (done + (held ? 1 : 0)) / total;
      verdict.textContent = t('challenge-checking', {
        done: integer(done + (held ? 1 : 0)),
        runs: integer(total),
        variants: integer(total - 1),
      });
    };
    tell(0);
    return this.pool.run(
      scenarios.map((scenario) => ({ kind: 'challenge-run', scenario })),
      tell,
    );
  }

  /**
   * Says why the student's settings are no answer, and that they were not run (`ran` false) or
   * not graded.
   * @param {Submission} sub
   * @param {boolean} ran
   */
  showRefusal(sub, ran) {
    const args = { reason: sub.message ?? '' };
    this.fail(t(ran ? 'challenge-refusal-not-graded' : 'challenge-refusal-not-run', args));
    this.parts.verdict.textContent = t(ran ? 'challenge-verdict-not-graded' : 'challenge-verdict-not-run', args);
    this.parts.checklist.replaceChildren();
    this.shown.forget();
    this.copyable(false);
    body().challenge = 'refused';
  }

  /**
   * Offers (or withholds) the submission link of the settings just checked; a word that an
   * earlier link was copied is about that link, so it goes.
   * @param {boolean} on
   */
  copyable(on) {
    this.parts.copy.disabled = !on;
    this.parts.copied.textContent = '';
  }

  async copySubmission() {
    const url = `${location.origin}${location.pathname}${location.search}`;
    const { copied } = this.parts;
    try {
      await navigator.clipboard.writeText(url);
      copied.textContent = t('challenge-copied');
    } catch {
      copied.textContent = t('challenge-copy-by-hand', { url });
    }
  }
}
