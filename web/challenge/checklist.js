// The challenge's checklist: the core's verdict on a student's runs, written as a line and a list
// of criteria, each with its value, its bound and its mark.
import { excerpt } from '../ui/quote.js';
import { el } from '../ui/dom.js';

/** A measured value as the checklist writes it. */
export function formatValue(value, unit) {
  if (value === null || value === undefined) return 'not measured';
  if (value === Infinity) return 'never (∞)';
  const u = unit ? ` ${unit}` : '';
  return `${Number(value.toPrecision(4))}${u}`;
}

export const plural = (n, word) => `${n} ${word}${n === 1 ? '' : 's'}`;

/**
 * The core's verdict `result` on submission `sub` as a checklist: each criterion's value, bound and
 * mark, in words and symbols, in the `verdict` line and the `checklist` list.
 */
export function showVerdict({ verdict, checklist }, result, sub) {
  const met = result.criteria.filter((c) => c.pass).length;
  const runs = sub.scenarios.length;
  const over = runs > 1 ? ` (the nominal run and ${plural(runs - 1, 'variant')})` : '';
  verdict.textContent = result.pass
    ? `✓ Passed: ${result.criteria.length === 1 ? 'the criterion is' : `all ${result.criteria.length} criteria are`} met${over}.`
    : `✗ Not passed: ${met} of ${result.criteria.length} criteria met${over}.`;
  checklist.replaceChildren(
    ...result.criteria.map((c) => {
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
