// The line that shows a step's own law's verdict, beside the law's field: in the walkthrough's
// step and in the settings form. The verdicts fill it (web/teaching/law-editor.js).
import { el } from './dom.js';
import { t } from '../l10n/l10n.js';

/**
 * What a step without a law of its own runs.
 * @param {number} step
 */
export const paperLaw = (step) => t('law-paper-default', { step });

/**
 * The line that shows step `step`'s verdict, saying what it runs until a verdict comes. It belongs to the
 * nearest element marked `data-law-scope` around it, which holds the step's formula input. With
 * `quiet`, a screen reader does not announce it (a second copy of a line announced elsewhere).
 * @param {number} step
 * @param {boolean} [quiet]
 */
export function verdictLine(step, quiet = false) {
  const line = el('p', { className: 'law-verdict', role: 'status', textContent: paperLaw(step) });
  line.dataset.lawStep = String(step);
  if (quiet) line.setAttribute('aria-live', 'off');
  return line;
}
