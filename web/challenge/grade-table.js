// The table of a class's grading: one short row per submission, with its carried columns (the
// student's name, say), its line, its verdict, each criterion's value as the core judged it, and
// the link. A criterion's label and bound stand in its column's header, so that a row is one line;
// a cause (why a link was refused, why a value was not measured) folds into its cell, the whole
// text a click away and in the cell's text for a screen reader. Every header sorts the rows by
// its column (again: the other way); the rows stay sorted as the results come in.
import { el } from '../ui/dom.js';
import { formatValue, withUnit } from './checklist.js';
import { t } from '../l10n/l10n.js';

/**
 * @import * as P from '../worker/protocol.js'
 */

/**
 * A graded submission as the table and the CSV need it: the core's status (its message), pass,
 * CSV line (in English, as `imlab grade` writes it) and verdict (null when its runs were not
 * judged).
 * @typedef {{status: P.Jobs['grade-link']['result']['status'] | string, pass: boolean, csv: string,
 *   verdict: P.Jobs['grade-link']['result']['verdict']}} Result
 */

/**
 * What the table shows: the carried columns' headers, each submission's line and its text as
 * the core shows it, the challenge's criteria (their labels and bounds the core's messages), and
 * the results by submission.
 * @typedef {{columns: string[], rows: {line: number}[], shown: {carried: string[], link: string}[],
 *   need: P.Jobs['challenge']['result']['need'], results: Record<number, Result>}} Shown
 */

/**
 * A column: its id, its header, its cell for submission `i`, and the key it sorts by (a number or
 * a text; null for a cell with nothing to sort by, which sorts last either way).
 * @typedef {{id: string, head: (Node | string)[], cell: (i: number) => HTMLTableCellElement,
 *   key: (i: number) => number | string | null}} Column
 */

// Names and other texts sort as a reader expects: case aside, and 'Student 2' before 'Student 10'.
const collator = new Intl.Collator(undefined, { numeric: true, sensitivity: 'base' });

/**
 * A cause folded into its cell: `summary` shown (cut short by the style sheet), the whole `text`
 * under it when opened, and in the summary's title.
 * @param {string} summary
 * @param {string} text
 */
function cause(summary, text) {
  return el('details', { className: 'cause' }, [
    el('summary', { textContent: summary, title: text }),
    el('div', { textContent: text }),
  ]);
}

/**
 * The verdict cell of a submission's `result` (none before it is graded).
 * @param {Result | undefined} result
 */
function verdictCell(result) {
  if (!result) return el('td', { className: 'pending', textContent: t('grade-pending') });
  if (result.verdict)
    return el('td', {
      className: result.pass ? 'pass' : 'fail',
      textContent: t(result.pass ? 'grade-pass' : 'grade-fail'),
    });
  return el('td', { className: 'fail' }, [cause(`✗ ${result.status}`, result.status)]);
}

/**
 * The cell of criterion `k` in `result`: its value as the checklist writes it (the unit is in
 * the header) and its mark; the exact value, the run it comes from and why it fails a click away.
 * @param {Result | undefined} result
 * @param {number} k
 */
function criterionCell(result, k) {
  const c = result?.verdict?.criteria[k];
  if (!c) return el('td', { className: 'value' });
  const shown = `${formatValue(c.value)} ${c.pass ? '✓' : '✗'}`;
  // The value in full (the CSV's digits, but for an exponent on the tiniest), or why there is none.
  const reason = c.reason ? c.reason : '';
  const exact = c.value === null ? reason : withUnit(String(c.value), c.unit);
  const words = c.pass || c.value === null ? exact : t('grade-value-reason', { value: exact, reason });
  const text = c.run === 'nominal' ? words : t('grade-worst-run', { text: words, run: c.run });
  const td = c.pass ? el('td', { textContent: shown, title: text }) : el('td', {}, [cause(shown, text)]);
  td.className = `value ${c.pass ? 'pass' : 'fail'}`;
  return td;
}

/**
 * The header of criterion `k`: its label, and its bound in the core's words.
 * @param {Shown} shown
 * @param {number} k
 */
function criterionHead(shown, k) {
  const need = shown.need[k];
  return [
    el('span', { className: 'label', textContent: need.label }),
    ' ',
    el('span', { className: 'bound', textContent: need.bound_text }),
  ];
}

/**
 * The columns of `shown`.
 * @param {Shown} shown
 * @returns {Column[]}
 */
function columnsOf(shown) {
  const result = (/** @type {number} */ i) => shown.results[i];
  /** @type {Column[]} */
  const carried = shown.columns.map((name, j) => ({
    id: `carried:${name}`,
    head: [name],
    cell: (i) => el('td', { className: 'carried', textContent: shown.shown[i].carried[j] }),
    key: (i) => shown.shown[i].carried[j],
  }));
  /** @type {Column[]} */
  const criteria = shown.need.map((n, k) => ({
    id: `need:${n.figure}`,
    head: criterionHead(shown, k),
    cell: (i) => criterionCell(result(i), k),
    key: (i) => result(i)?.verdict?.criteria[k]?.value ?? null,
  }));
  return [
    ...carried,
    {
      id: 'line',
      head: [t('grade-head-line')],
      cell: (i) => el('td', { textContent: String(shown.rows[i].line) }),
      key: (i) => shown.rows[i].line,
    },
    {
      id: 'verdict',
      head: [t('grade-head-verdict')],
      cell: (i) => verdictCell(result(i)),
      // Passed, failed, then not judged (refused, malformed…); not graded yet last.
      key: (i) => (result(i) ? (result(i).verdict ? (result(i).pass ? 0 : 1) : 2) : null),
    },
    ...criteria,
    {
      id: 'link',
      head: [t('grade-head-link')],
      cell: (i) => el('td', { className: 'link', textContent: shown.shown[i].link, title: shown.shown[i].link }),
      key: (i) => shown.shown[i].link,
    },
  ];
}

/**
 * -1, 0 or 1 as `a` sorts before, with or after `b`; a missing key after any other.
 * @param {number | string | null} a
 * @param {number | string | null} b
 * @param {number} dir 1 ascending, -1 descending
 */
function compare(a, b, dir) {
  if (a === null || b === null) return a === b ? 0 : a === null ? 1 : -1;
  if (typeof a === 'string' && typeof b === 'string') return dir * collator.compare(a, b);
  return dir * (a < b ? -1 : a > b ? 1 : 0);
}

/** The table of a grading, sortable by any column. */
export class GradeTable {
  /** @param {HTMLTableElement} table */
  constructor(table) {
    this.table = table;
    /** @type {Shown | null} */
    this.shown = null;
    /** @type {Column[]} */
    this.columns = [];
    /** @type {HTMLTableRowElement[]} each submission's row, by index */
    this.rows = [];
    /** The column the rows are sorted by, and which way: the class file's order to begin with. */
    this.sort = { id: 'line', descending: false };
    table.addEventListener('click', (e) => {
      const button = /** @type {Element} */ (e.target).closest('th button');
      if (!(button instanceof HTMLButtonElement) || !button.dataset.column) return;
      const id = button.dataset.column;
      this.sort = { id, descending: this.sort.id === id && !this.sort.descending };
      this.order();
    });
  }

  /**
   * Draws `shown`: a row for each submission, graded or not yet.
   * @param {Shown} shown
   */
  draw(shown) {
    this.shown = shown;
    this.columns = columnsOf(shown);
    if (!this.columns.some((c) => c.id === this.sort.id)) this.sort = { id: 'line', descending: false };
    const heads = this.columns.map((c) => {
      const button = el('button', { type: 'button', className: 'sort' }, c.head);
      button.dataset.column = c.id;
      return el('th', { scope: 'col' }, [button]);
    });
    this.rows = shown.rows.map((_, i) => this.rowOf(i));
    this.table.replaceChildren(el('thead', {}, [el('tr', {}, heads)]), el('tbody', {}, this.rows));
    this.order();
  }

  /**
   * Shows submission `i`'s result, in its place in the sorted rows.
   * @param {number} i
   */
  update(i) {
    const row = this.rowOf(i);
    this.rows[i].replaceWith(row);
    this.rows[i] = row;
    if (this.sort.id !== 'line') this.order();
    else this.marks();
  }

  /**
   * Submission `i`'s row.
   * @param {number} i
   */
  rowOf(i) {
    const cells = this.columns.map((c) => c.cell(i));
    // The first cell (the student's name, or else the line) names the row.
    const name = el('th', { scope: 'row', className: cells[0].className, title: cells[0].title }, [
      ...cells[0].childNodes,
    ]);
    const tr = el('tr', {}, [name, ...cells.slice(1)]);
    const result = this.shown?.results[i];
    tr.dataset.index = String(i);
    if (result) tr.dataset.pass = result.pass ? '1' : '0';
    return tr;
  }

  /** Puts the rows in the order of the sort, and says it in the headers. */
  order() {
    const column = /** @type {Column} */ (this.columns.find((c) => c.id === this.sort.id));
    const dir = this.sort.descending ? -1 : 1;
    const keys = this.rows.map((_, i) => column.key(i));
    const sorted = this.rows.map((_, i) => i).sort((a, b) => compare(keys[a], keys[b], dir) || a - b);
    this.table.tBodies[0].append(...sorted.map((i) => this.rows[i]));
    this.marks();
  }

  /** Says the sort in its column's header, by `aria-sort` (which the style sheet shows as an arrow). */
  marks() {
    for (const th of this.table.tHead?.rows[0].cells ?? []) {
      if (/** @type {HTMLElement} */ (th.firstChild).dataset.column !== this.sort.id) th.removeAttribute('aria-sort');
      else th.setAttribute('aria-sort', this.sort.descending ? 'descending' : 'ascending');
    }
  }
}
