// The challenge panel's knobs: one control for each field the challenge allows, with its range;
// its edits go to the settings form, which the run reads.
import { ui } from '../ui/page.js';
import { el } from '../ui/dom.js';
import { setField } from '../run/controls.js';
import { t } from '../l10n/l10n.js';

/** @import * as P from '../worker/protocol.js' */

/**
 * A field the challenge allows (the core's description of it), and a panel knob's control.
 * @typedef {P.Jobs['challenge']['result']['allow'][number]} Allowed
 * @typedef {HTMLInputElement | HTMLSelectElement} Control
 */

/**
 * Copies a panel knob's value to the settings form's control of `field` (the run reads the form).
 * @param {string} field
 * @param {Control} control
 */
export const copyToForm = (field, control) => setField(ui.form, field, control.value);

/**
 * The panel's control for an allowed field `a` (the core's description), kept in `knobs` by field;
 * its edits go to the settings form.
 * @param {Allowed} a
 * @param {Map<string, Control>} knobs
 */
export function knob(a, knobs) {
  const id = `challenge-${a.field}`;
  const control = /** @type {Control} */ (
    a.kind === 'choice'
      ? el(
          'select',
          { name: a.field, id },
          a.options.map((/** @type {string} */ o) => el('option', { value: o, textContent: o })),
        )
      : a.kind === 'formula'
        ? el('input', { type: 'text', name: a.field, id, spellcheck: false, className: 'formula', autocomplete: 'off' })
        : el('input', { type: 'text', inputMode: 'decimal', name: a.field, id, spellcheck: false })
  );
  control.value = a.value ?? '';
  const allowed = /** @type {Record<string, () => string>} */ ({
    choice: () => t('challenge-allowed-choice', { options: a.options.join(', ') }),
    formula: () => t('challenge-allowed-formula', { unit: a.unit }),
    range: () =>
      a.unit
        ? t('challenge-allowed-range-unit', { lo: String(a.lo), hi: String(a.hi), unit: a.unit })
        : t('challenge-allowed-range', { lo: String(a.lo), hi: String(a.hi) }),
  })[a.kind]();
  const rangeId = `${id}-range`;
  control.setAttribute('aria-describedby', rangeId);
  knobs.set(a.field, control);
  control.addEventListener('change', () => {
    copyToForm(a.field, control);
    ui.form.dispatchEvent(new Event('change'));
  });
  control.addEventListener('keydown', (e) => {
    if (/** @type {KeyboardEvent} */ (e).key !== 'Enter') return;
    e.preventDefault();
    copyToForm(a.field, control);
    ui.run.click();
  });
  return el('label', { htmlFor: id, className: 'field' }, [
    el('span', { className: 'key', textContent: a.field }),
    el('span', {
      className: 'doc',
      textContent: a.unit ? t('challenge-knob-doc', { doc: a.doc, unit: a.unit }) : a.doc,
    }),
    control,
    el('span', { className: 'range', id: rangeId, textContent: allowed }),
  ]);
}
