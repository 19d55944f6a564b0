// The challenge's checklist: the core's verdict on a student's runs, written as a line and a list
// of criteria, each with its value, its bound and its mark; and the panel's parts that hold it.
import { excerpt } from '../ui/quote.js';
import { el } from '../ui/dom.js';

/** @import * as P from '../worker/protocol.js' */

/**
 * The core's verdict on the runs of a submission, one of its criteria, and a submission read (its
 * status and the scenarios it runs).
 * @typedef {P.Jobs['challenge-judge']['result']} Verdict
 * @typedef {Verdict['criteria'][number]} Criterion
 * @typedef {P.Jobs['challenge-tries']['result']} Submission
 */

/**
 * A measured value as the checklist writes it.
 * @param {number | null | undefined} value
 * @param {string} [unit]
 */
export function formatValue(value, unit) {
  if (value === null || value === undefined) return 'not measured';
  if (value === Infinity) return 'never (∞)';
  const u = unit ? ` ${unit}` : '';
  return `${Number(value.toPrecision(4))}${u}`;
}

/**
 * `n` and `word`, the word in the plural unless `n` is 1: `3 runs`.
 * @param {number} n
 * @param {string} word
 */
export const plural = (n, word) => `${n} ${word}${n === 1 ? '' : 's'}`;

/**
 * The core's verdict `result` on submission `sub` as a checklist: each criterion's value, bound and
 * mark, in words and symbols, in the `verdict` line and the `checklist` list.
 * @param {{verdict: HTMLElement, checklist: HTMLElement}} parts
 * @param {Verdict} result
 * @param {Submission} sub
 */
export function showVerdict({ verdict, checklist }, result, sub) {
  const met = result.criteria.filter((/** @type {Criterion} */ c) => c.pass).length;
  const runs = sub.scenarios.length;
  const over = runs > 1 ? ` (the nominal run and ${plural(runs - 1, 'variant')})` : '';
  verdict.textContent = result.pass
    ? `✓ Passed: ${result.criteria.length === 1 ? 'the criterion is' : `all ${result.criteria.length} criteria are`} met${over}.`
    : `✗ Not passed: ${met} of ${result.criteria.length} criteria met${over}.`;
  checklist.replaceChildren(
    ...result.criteria.map((/** @type {Criterion} */ c) => {
      const where = c.run === 'nominal' ? '' : ` (worst run: ${excerpt(c.run)})`;
      const li = el('li', { className: c.pass ? 'pass' : 'fail' }, [
        el('strong', { className: 'mark', textContent: c.pass ? '✓ pass' : '✗ fail' }),
        ` ${c.label}: `,
        el('span', { className: 'value', textContent: formatValue(c.value, c.unit) }),
        `, needs ${c.bound}${where}`,
        ...(c.reason ? [el('span', { className: 'reason', textContent: ` — ${c.reason}` })] : []),
      ]);
      li.dataset.figure = c.figure;
      li.dataset.pass = c.pass ? '1' : '0';
      return li;
    }),
  );
}

/**
 * The panel's parts that outlive a render: the checklist, the check's progress and the copy.
 * @returns {{checklist: HTMLElement, verdict: HTMLElement, progress: HTMLProgressElement, cancel: HTMLButtonElement,
 *   copy: HTMLButtonElement, copied: HTMLElement, alert: HTMLElement}}
 */
export function panelParts() {
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
