// The challenge's checklist: the core's verdict on a student's runs, written as a line and a list
// of criteria, each with its value, its bound and its mark; and the panel's parts that hold it.
import { excerpt } from '../ui/quote.js';
import { el } from '../ui/dom.js';
import { t } from '../l10n/l10n.js';
import { integer, sig } from '../analysis/digits.js';

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
  if (value === null || value === undefined) return t('checklist-not-measured');
  if (value === Infinity) return t('checklist-never');
  return withUnit(sig(value, 4), unit);
}

/**
 * A value, already written, and its unit (the core's), if any.
 * @param {string} value
 * @param {string} [unit]
 */
export const withUnit = (value, unit) => (unit ? t('checklist-value-unit', { value, unit }) : value);

// Stands for an element in a message's text, which is split around it.
const SLOT = '\u0000';

/**
 * The message `id` with `args`, its variable `slot` given as `node`: the text around it and the
 * node, to append to an element (a message's words keep their order around the node).
 * @param {string} id
 * @param {Record<string, string | import('@fluent/bundle').FluentNumber>} args
 * @param {string} slot
 * @param {Node} node
 * @returns {(Node | string)[]}
 */
function around(id, args, slot, node) {
  const [before, after = ''] = t(id, { ...args, [slot]: SLOT }).split(SLOT);
  return [before, node, after].filter((part) => part !== '');
}

/**
 * The verdict line of `result`, a check over `runs` runs (the nominal one and any variants).
 * @param {Verdict} result
 * @param {number} runs
 */
function verdictLine(result, runs) {
  const args = {
    met: integer(result.criteria.filter((/** @type {Criterion} */ c) => c.pass).length),
    criteria: integer(result.criteria.length),
    variants: integer(runs - 1),
  };
  if (runs > 1) return t(result.pass ? 'checklist-passed-variants' : 'checklist-failed-variants', args);
  return t(result.pass ? 'checklist-passed' : 'checklist-failed', args);
}

/**
 * The core's verdict `result` on submission `sub` as a checklist: each criterion's value, bound and
 * mark, in words and symbols, in the `verdict` line and the `checklist` list.
 * @param {{verdict: HTMLElement, checklist: HTMLElement}} parts
 * @param {Verdict} result
 * @param {Submission} sub
 */
export function showVerdict({ verdict, checklist }, result, sub) {
  verdict.textContent = verdictLine(result, sub.scenarios.length);
  checklist.replaceChildren(
    ...result.criteria.map((/** @type {Criterion} */ c) => {
      const value = el('span', { className: 'value', textContent: formatValue(c.value, c.unit) });
      const [id, run] =
        c.run === 'nominal' ? ['checklist-criterion', ''] : ['checklist-criterion-worst', excerpt(c.run)];
      const li = el('li', { className: c.pass ? 'pass' : 'fail' }, [
        el('strong', { className: 'mark', textContent: t(c.pass ? 'checklist-pass' : 'checklist-fail') }),
        ' ',
        ...around(id, { label: c.label, bound: c.bound, run }, 'value', value),
        ...(c.reason
          ? [el('span', { className: 'reason', textContent: ` ${t('checklist-reason', { reason: c.reason })}` })]
          : []),
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
  progress.setAttribute('aria-label', t('challenge-progress.aria-label'));
  const cancel = el('button', {
    type: 'button',
    id: 'challenge-cancel',
    textContent: t('challenge-cancel'),
    disabled: true,
  });
  const copy = el('button', {
    type: 'button',
    id: 'challenge-copy',
    textContent: t('challenge-copy'),
    disabled: true,
  });
  const copied = el('p', { className: 'hint', id: 'challenge-copied', role: 'status' });
  const alert = el('p', { id: 'challenge-error', className: 'challenge-error', role: 'alert' });

  return { checklist, verdict, progress, cancel, copy, copied, alert };
}
