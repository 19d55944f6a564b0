// The Challenge tab, for the lecturer: composes a challenge from the scenario in the form (its
// base), the fields a student may change with their ranges, criteria on the figures of the
// current run with their bounds, and robustness variants. The core checks the link and writes
// it and the task in words, both to copy; its message names the field at fault. Then the page
// checks that a design within the allowed ranges passes (compose-check.js) and says so. This
// browser records each challenge it makes (origin.js), so that its link opened here says so.
import { $ } from '../ui/page.js';
import { el } from '../ui/dom.js';
import { allowSet, button, needSet, varySet } from './compose-rows.js';
import { createCheck } from './compose-check.js';
import { remember } from './origin.js';
import { t } from '../l10n/l10n.js';
import { withLanguage } from '../ui/language.js';
import { briefText } from './brief.js';

/**
 * @import * as P from '../worker/protocol.js'
 * @import { RunClient } from '../client/run-client.js'
 * @import { PageState } from './challenge.js'
 */

/**
 * A challenge the core composed: its link and its task in words (paragraphs of its messages).
 * @typedef {{encoded: string, brief: import('./brief.js').Brief}} Composed
 */

/**
 * What "Make the challenge link" shows for the core's `desc` ({encoded, brief}): the link and the
 * task in words (in the language shown), each with its copy button, `checkBox` (the check's)
 * beside the link, and whether this browser `kept` the record that it composed the challenge.
 * @param {Composed} desc
 * @param {HTMLElement} checkBox
 * @param {boolean} kept
 */
function made(desc, checkBox, kept) {
  const url = withLanguage(`${location.origin}${location.pathname}?${desc.encoded}`);
  const brief = briefText(desc.brief);
  const linkBox = el('textarea', { id: 'compose-link', readOnly: true, rows: 3, value: url });
  const briefBox = el('textarea', { id: 'compose-brief', readOnly: true, rows: 12, value: brief });
  const copied = el('p', { className: 'hint', role: 'status' });
  /**
   * A button labelled `label` that copies `text2`, and says so by the message `said`, or that the
   * browser refused by the message `refused`.
   * @param {string} id
   * @param {string} label
   * @param {string} text2
   * @param {string} said
   * @param {string} refused
   */
  const copier = (id, label, text2, said, refused) =>
    button(id, label, async () => {
      try {
        await navigator.clipboard.writeText(text2);
        copied.textContent = t(said);
      } catch {
        copied.textContent = t(refused);
      }
    });
  return [
    el('label', { htmlFor: 'compose-link', textContent: t('compose-link') }),
    linkBox,
    el('p', {
      id: 'compose-kept',
      className: 'hint',
      textContent: t(kept ? 'compose-kept' : 'compose-not-kept'),
    }),
    el('div', { className: 'buttons' }, [
      copier('compose-copy-link', t('compose-copy-link'), url, 'compose-link-copied', 'compose-link-not-copied'),
      el('a', {
        href: `?${desc.encoded}`,
        id: 'compose-open',
        textContent: t('compose-open'),
        target: '_blank',
        rel: 'noopener',
      }),
    ]),
    checkBox,
    el('label', { htmlFor: 'compose-brief', textContent: t('compose-brief') }),
    briefBox,
    el('div', { className: 'buttons' }, [
      copier('compose-copy-brief', t('compose-copy-brief'), brief, 'compose-brief-copied', 'compose-brief-not-copied'),
    ]),
    copied,
  ];
}

/**
 * The compose form in `box`; `client` is the page's worker and `state` the page's state.
 * @param {{client: RunClient, state: PageState}} page
 */
export function createCompose({ client, state }) {
  const box = $('compose');
  const status = el('p', { id: 'compose-status', className: 'hint', role: 'status' });
  const error = el('p', { id: 'compose-error', className: 'challenge-error', role: 'alert', hidden: true });
  const output = el('div', { id: 'compose-output', hidden: true });
  /** @type {P.Jobs['challenge-figures']['result'] | null} what criteria may name, from the core */
  let figures = null;
  /** @type {P.Info | null} the scenario the form was filled from */
  let base = null;
  const checker = createCheck({ client });

  async function fill() {
    const info = state.info;
    if (!info) return;
    figures ??= await client.job('challenge-figures');
    // The figures of the run on screen, when it is the form's scenario.
    let measures = null;
    if (state.ranScenario === info.encoded && !state.running && state.runId > 0)
      measures = await client.measure(state.runId).catch(() => null);
    base = info;
    checker.stop();
    output.hidden = true;
    fail('');
    box.replaceChildren(
      el('p', {
        className: 'hint',
        textContent: t('compose-intro'),
      }),
      el('p', { className: 'compose-base' }, [t('compose-base'), ' ', el('code', { textContent: info.encoded })]),
      el('label', { className: 'compose-title' }, [
        t('compose-title'),
        ' ',
        el('input', {
          id: 'compose-title',
          value: t('compose-title-default', { preset: info.preset }),
          maxLength: 120,
        }),
      ]),
      allowSet(info),
      needSet(figures, measures),
      varySet(info),
      el('div', { className: 'buttons' }, [button('compose-make', t('compose-make'), make)]),
      error,
      output,
    );
    status.textContent = measures ? '' : t('compose-no-run');
    box.prepend(status);
    document.body.dataset.compose = 'filled';
  }

  /**
   * Shows the error `text` (empty clears it) and marks the row of the part at fault, `key`.
   * @param {string} text
   * @param {string | null} [key]
   */
  function fail(text, key = null) {
    error.textContent = text;
    error.hidden = !text;
    for (const r of /** @type {NodeListOf<HTMLElement>} */ (box.querySelectorAll('[data-key]'))) {
      const bad = r.dataset.key === key;
      r.classList.toggle('invalid', bad);
      for (const c of r.querySelectorAll('input, select')) c.toggleAttribute('aria-invalid', bad);
    }
  }

  /** The parts of the challenge the form describes, for the core to check and write. */
  function parts() {
    /**
     * The value of the control named `name` in `row`.
     * @param {HTMLElement} row
     * @param {string} name
     */
    const value = (row, name) =>
      /** @type {HTMLInputElement | HTMLSelectElement} */ (row.querySelector(`[name=${name}]`)).value;
    const allow = /** @type {HTMLElement[]} */ ([...$('compose-allow').children]).map((row) =>
      row.querySelector('[name=options]')
        ? { field: row.dataset.field, options: value(row, 'options') }
        : { field: row.dataset.field, lo: value(row, 'lo'), hi: value(row, 'hi') },
    );
    const used = /** @type {HTMLElement[]} */ ([...$('compose-need').children]).filter(
      (row) => /** @type {HTMLInputElement} */ (row.querySelector('[name=use]')).checked,
    );
    return {
      title: $('compose-title', HTMLInputElement).value,
      // The form is filled before its Make button exists.
      base: /** @type {P.Info} */ (base).encoded,
      allow,
      need: used.map((row) => ({ figure: row.dataset.figure, op: value(row, 'op'), bound: value(row, 'bound') })),
      vary: $('compose-vary', HTMLInputElement).value,
      robust: used
        .filter((row) => /** @type {HTMLInputElement} */ (row.querySelector('[name=robust]')).checked)
        // Every criterion's row names its figure (compose-rows.js).
        .map((row) => /** @type {string} */ (row.dataset.figure)),
    };
  }

  async function make() {
    const desc = await client.job('challenge-compose', { parts: parts() });
    if (desc.error) {
      fail(t('compose-invalid', { reason: desc.error.message }), desc.error.key);
      output.hidden = true;
      checker.stop();
      document.body.dataset.compose = 'invalid';
      return;
    }
    // Without an error, the core gives the link and the task.
    const composed = /** @type {Composed} */ (desc);
    const kept = await remember(composed.encoded);
    fail('');
    output.replaceChildren(...made(composed, checker.box, kept));
    output.hidden = false;
    document.body.dataset.compose = 'made';
    checker.check(composed.encoded);
  }

  let filled = false;
  const fillOnce = () => {
    if (!filled && state.info) {
      filled = true;
      fill();
    }
  };
  const fillButton = $('compose-fill', HTMLButtonElement);
  fillButton.addEventListener('click', fill);
  fillButton.disabled = false;
  $('tab-challenge', HTMLButtonElement).addEventListener('click', fillOnce);
  // Made when the tab is first shown, the form is filled at once.
  if (!$('panel-challenge', HTMLDivElement).hidden) fillOnce();
}
