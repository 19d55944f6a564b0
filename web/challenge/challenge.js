// The challenge a link opens, for the student: the task, the knobs it allows (the other settings
// locked), and the checklist of its criteria, judged by the core after every run on the nominal
// run and on each robustness variant (run in a pool of workers, with progress and Cancel). The
// address then holds the student's submission link. The built-in challenges are listed in the
// Lessons tab.
import { $, ui } from '../ui/page.js';
import { fieldValue } from '../run/controls.js';
import { Pool } from '../client/pool.js';
import { challengeFromUrl, holdAddress, scenarioFromUrl } from '../ui/url.js';
import { el } from '../ui/dom.js';
import { plural, showVerdict } from './checklist.js';
import { copyToForm, knob } from './knobs.js';

/** The panel's parts that outlive a render: the checklist, the check's progress and the copy. */
function panelParts() {
  const checklist = el('ul', { className: 'checklist', id: 'challenge-checklist' });
  const verdict = el('p', { id: 'challenge-verdict', className: 'verdict', role: 'status' });
  const progress = el('progress', { id: 'challenge-progress', max: 1, value: 0, hidden: true });
  progress.setAttribute('aria-label', 'Challenge runs done');
  const cancel = el('button', { type: 'button', id: 'challenge-cancel', textContent: 'Cancel check', disabled: true });
  const copy = el('button', {
    type: 'button',
    id: 'challenge-copy',
    textContent: 'Copy submission link',
    disabled: true,
  });
  const copied = el('p', { className: 'hint', id: 'challenge-copied', role: 'status' });
  const alert = el('p', { id: 'challenge-error', className: 'challenge-error', role: 'alert' });

  return { checklist, verdict, progress, cancel, copy, copied, alert };
}

/**
 * The student's side of a challenge; `client` is the page's worker, `relayout()` sizes the plots
 * to the room the panel leaves them.
 */
export function createChallenge({ client, state, relayout }) {
  const panel = $('challenge-panel');
  const link = challengeFromUrl();
  let desc = null; // the core's description of the open challenge
  let refused = null; // why the link's submission was refused, until the student runs their own
  let grading = 0; // checks started: a newer one supersedes the one under way
  let pool = null; // workers for the variants, started at the first check that has some
  const knobs = new Map(); // field → the panel's control
  const body = document.body.dataset;

  const { checklist, verdict, progress, cancel, copy, copied, alert } = panelParts();

  /** Shows the error `text` in the panel (empty clears it). */
  function fail(text) {
    alert.textContent = text;
    alert.hidden = !text;
  }

  /**
   * Opens the challenge in the address, if any: shows its task and resolves with the scenario of
   * its nominal run (the link's settings, or the base's when they are refused). Without a
   * challenge (or with one the core rejects) it resolves with the address's scenario.
   */
  async function open() {
    if (!link) return scenarioFromUrl();
    try {
      return await openLink();
    } catch (e) {
      fail(`The challenge could not be opened: ${e.message}. The page shows the default scenario instead.`);
      body.challenge = 'failed';
      desc = null;
      return scenarioFromUrl();
    }
  }

  async function openLink() {
    document.body.classList.add('with-challenge');
    panel.hidden = false;
    body.challenge = 'loading';
    panel.replaceChildren(el('h2', { textContent: 'Challenge' }), alert);
    try {
      desc = await client.job('challenge', { text: link.challenge });
    } catch (e) {
      fail(`This challenge link was rejected: ${e.message}. The page shows the default scenario instead.`);
      body.challenge = 'malformed';
      return scenarioFromUrl();
    }
    let sub = await client.job('challenge-submission', {
      text: desc.encoded,
      submission: link.submission ?? desc.encoded,
    });
    if (sub.kind !== 'ok') {
      refused =
        sub.kind === 'another'
          ? 'This submission link belongs to another challenge (its challenge part was edited): it was not graded.'
          : `This submission link was ${sub.kind === 'refused' ? 'refused' : 'rejected'}: ${sub.message}. It was not graded; the task starts from its base settings.`;
      sub = await client.job('challenge-submission', { text: desc.encoded, submission: desc.encoded });
    }
    holdAddress(refused ? location.search.slice(1) : sub.encoded);
    render();
    if (refused) {
      fail(refused);
      body.challenge = 'refused';
    } else body.challenge = 'open';
    return sub.scenarios[0];
  }

  function render() {
    const task = el('details', { className: 'brief', open: true }, [
      el('summary', { textContent: 'The task in full' }),
      el('div', { className: 'brief-text', textContent: desc.brief.split('\n').slice(2).join('\n').trim() }),
    ]);
    const run = el('button', { type: 'button', id: 'challenge-run', textContent: 'Run and check' });
    run.addEventListener('click', () => {
      for (const [field, control] of knobs) copyToForm(field, control);
      ui.run.click();
    });
    const knobBox = el('div', { className: 'knobs challenge-knobs' });
    for (const a of desc.allow) knobBox.append(knob(a, knobs));
    copy.addEventListener('click', copySubmission);
    cancel.addEventListener('click', () => pool?.cancel());
    panel.replaceChildren(
      el('p', { className: 'lesson-count', textContent: 'Challenge' }),
      el('h2', { textContent: desc.title, tabIndex: -1 }),
      alert,
      el('h3', { textContent: 'Your settings' }),
      el('p', {
        className: 'hint',
        textContent: `Only ${desc.allow.map((a) => a.field).join(', ')} can be changed; the other settings are locked by the challenge.`,
      }),
      knobBox,
      el('div', { className: 'buttons' }, [run, cancel]),
      progress,
      el('h3', { textContent: 'Checklist' }),
      verdict,
      checklist,
      el('div', { className: 'buttons' }, [copy]),
      copied,
      task,
    );
    relayout();
    verdict.textContent = 'Not checked yet: the first run is being computed.';
    checklist.replaceChildren(
      ...desc.need.map((n) => el('li', { textContent: `${n.label} (${n.figure}): not checked yet` })),
    );
  }

  /** After each description of the form: only the allowed fields stay editable, and the panel follows the form. */
  function described(info) {
    if (!desc) return;
    ui.preset.disabled = true;
    const allowed = new Set(desc.allow.map((a) => a.field));
    const controls = /** @type {NodeListOf<HTMLInputElement | HTMLSelectElement>} */ (
      document.querySelectorAll(
        '#settings input, #settings select, #walkthrough .knobs input, #walkthrough .knobs select',
      )
    );
    for (const c of controls) {
      c.disabled = !allowed.has(c.name);
    }
    for (const [field, control] of knobs) {
      if (control !== document.activeElement) control.value = fieldValue(info, field) ?? '';
    }
  }

  /** The description of the scenario run last (the form's, unless it has been edited since). */
  const ranInfo = () => (state.info.encoded === state.ranScenario ? state.info : client.describe(state.ranScenario));

  /**
   * Checks the run that just ended: the student's settings as a submission, the measures of the
   * nominal run (this run's, when it is the one the challenge asks for) and of each variant, and
   * the core's verdict on them.
   */
  async function check() {
    if (!desc) return;
    const me = ++grading;
    const runId = state.runId;
    if (refused && runId === 1) {
      verdict.textContent =
        '✗ Not graded: the settings in the link were refused (see above). Change the allowed settings and run.';
      body.challengeChecked = runId;
      return;
    }
    refused = null;
    fail('');
    pool?.cancel();
    body.challenge = 'checking';
    try {
      const info = await ranInfo();
      const tries = desc.allow
        .map((a) => [a.field, fieldValue(info, a.field)])
        .filter(([f, v]) => v !== null && v !== desc.allow.find((a) => a.field === f).value);
      const sub = await client.job('challenge-tries', { text: desc.encoded, tries });
      if (me !== grading) return;
      if (sub.kind !== 'ok') {
        showRefusal(sub);
        return;
      }
      const held = sub.scenarios[0] === state.ranScenario ? await client.measure(runId) : null;
      body.challengeNominal = held ? 'page' : 'pool';
      const measured = await measureRuns(held ? sub.scenarios.slice(1) : sub.scenarios, held !== null);
      if (me !== grading) return;
      const result = await client.job('challenge-judge', {
        text: desc.encoded,
        runs: held ? [held, ...measured] : measured,
      });
      if (me !== grading) return;
      showVerdict({ verdict, checklist }, result, sub);
      if (!held)
        verdict.append(
          ' The run on screen is not the graded one (a locked setting differs): the nominal run was run again with the challenge’s settings and your allowed ones.',
        );
      holdAddress(sub.encoded);
      copy.disabled = false;
      body.challenge = result.pass ? 'pass' : 'fail';
    } catch (e) {
      if (me !== grading) return;
      const cancelled = e.message === 'cancelled';
      verdict.textContent = cancelled
        ? '✗ Check cancelled: not graded. Run again to check.'
        : `✗ The check failed: ${e.message}. Not graded.`;
      body.challenge = cancelled ? 'cancelled' : 'failed';
    } finally {
      if (me === grading) {
        progress.hidden = true;
        cancel.disabled = true;
        body.challengeChecked = runId;
      }
    }
  }

  /**
   * Measures `scenarios` in the pool with progress (the nominal run is the first of them unless
   * the page `held` it); rejects with 'cancelled' on Cancel.
   */
  async function measureRuns(scenarios, held) {
    if (!scenarios.length) return [];
    pool ??= new Pool(1);
    pool.size = Math.max(1, Math.min(scenarios.length, 4, navigator.hardwareConcurrency || 2));
    progress.hidden = false;
    progress.value = 0;
    cancel.disabled = false;
    const total = scenarios.length + (held ? 1 : 0);
    const tell = (done) => {
      progress.value = (done + (held ? 1 : 0)) / total;
      verdict.textContent = `Checking: ${done + (held ? 1 : 0)} of ${plural(total, 'run')} done (the nominal run and ${plural(total - 1, 'variant')})…`;
    };
    tell(0);
    return pool.run(
      scenarios.map((scenario) => ({ kind: 'challenge-run', scenario })),
      tell,
    );
  }

  function showRefusal(sub) {
    const text = `Your settings are not a valid answer: ${sub.message}.`;
    fail(text);
    verdict.textContent = `✗ Not graded. ${text}`;
    checklist.replaceChildren();
    copy.disabled = true;
    body.challenge = 'refused';
  }

  async function copySubmission() {
    const url = `${location.origin}${location.pathname}${location.search}`;
    try {
      await navigator.clipboard.writeText(url);
      copied.textContent = 'Submission link copied: it replays these runs bit for bit.';
    } catch {
      copied.textContent = `Copy this submission link: ${url}`;
    }
  }

  return { open, described, check, active: () => link !== null && desc !== null };
}
