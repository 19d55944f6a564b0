// The teaching text's numbers: a lesson is a template that names measurements ({id}), and the
// measurements table (web/teaching/measurements/*.csv, computed by `imlab claims`) gives their
// values. A sentence keeps its words and its numbers apart, so a number changes only with the
// table, and a translation of the words keeps the same numbers.

/**
 * @typedef {{ value: number, show: string, seeds: string, statistic: string }} Measured
 * @typedef {Map<string, Measured>} Table
 */

/**
 * The rows of measurements tables (CSV, as `imlab claims` writes them), by id.
 * @param {string[]} texts
 * @returns {Table}
 */
export function parseTables(texts) {
  /** @type {Table} */
  const table = new Map();
  for (const text of texts) {
    const [header, ...lines] = text.trim().split('\n');
    const names = header.split(',');
    const col = (/** @type {string} */ name) => names.indexOf(name);
    for (const line of lines) {
      const cells = line.split(',');
      const value = cells[col('value')];
      if (value === '') throw new Error(`measurement ${cells[col('id')]} has no value: run imlab claims --write`);
      table.set(cells[col('id')], {
        value: value === 'inf' ? Infinity : value === '-inf' ? -Infinity : Number(value),
        show: cells[col('show')],
        seeds: cells[col('seeds')],
        statistic: cells[col('statistic')],
      });
    }
  }
  return table;
}

// How a `show` spec scales a value: ms for seconds, % for a fraction, m for milli (mrad/s, mWb²).
/** @type {Record<string, number>} */
const SCALES = { '': 1, ms: 1e3, '%': 1e2, m: 1e3 };

/**
 * `value` with `digits` significant digits, written as the page's sentences write numbers in
 * `locale` (English by default: a minus sign, thousands grouped by commas from five digits on).
 * `toward` rounds down (-1) or up (+1) instead of to the nearest: a least value shown is never
 * above it, and a largest never below it, so that "at most 1.95" is not shown as "at most 1.9".
 * @param {number} value
 * @param {number} digits
 * @param {number} [toward]
 * @param {string} [locale]
 */
export function significant(value, digits, toward = 0, locale = 'en') {
  let rounded = Number(value.toPrecision(digits));
  if (toward !== 0 && rounded !== value && value !== 0) {
    const step = 10 ** (Math.floor(Math.log10(Math.abs(value))) - digits + 1);
    // A value that is a whole number of steps, bar the last bit, rounds to itself.
    const steps = value / step;
    const near = Math.round(steps);
    const whole =
      Math.abs(steps - near) < 1e-9 * Math.abs(steps) ? near : toward < 0 ? Math.floor(steps) : Math.ceil(steps);
    rounded = Number((whole * step).toPrecision(digits + 1));
  }
  const magnitude = rounded === 0 ? 0 : Math.floor(Math.log10(Math.abs(rounded)));
  const fraction = Math.max(0, digits - 1 - magnitude);
  const text = new Intl.NumberFormat(locale, {
    useGrouping: 'min2',
    minimumFractionDigits: fraction,
    maximumFractionDigits: fraction,
  }).format(Math.abs(rounded));
  return `${rounded < 0 ? '−' : ''}${text}`;
}

/**
 * How the text shows a measured row: `count` a whole number, `SCALE:DIGITS` its value scaled
 * (ms, %, m for milli) to DIGITS significant digits; a row's least value (`min`) rounded down and
 * its largest (`max`) rounded up, so that a range shown holds every draw.
 * @param {Measured} m
 * @param {string} id
 * @param {string} [locale]
 */
export function shown(m, id, locale = 'en') {
  if (!Number.isFinite(m.value)) throw new Error(`measurement ${id} is ${m.value}: a text cannot state it`);
  if (m.show === 'count') {
    if (!Number.isInteger(m.value)) throw new Error(`measurement ${id} shown as a count is ${m.value}`);
    return String(m.value);
  }
  const [scale, digits] = m.show.split(':');
  if (!(scale in SCALES) || !/^[1-9]$/.test(digits)) throw new Error(`measurement ${id}: show '${m.show}'`);
  const toward = { min: -1, max: 1 }[m.statistic] ?? 0;
  return significant(m.value * SCALES[scale], Number(digits), toward, locale);
}

// A placeholder: {id}, or {id#draws} for the number of noise draws its sample takes.
const PLACEHOLDER = /\{([A-Za-z0-9._]+)(#draws)?\}/g;

/**
 * `template` with each placeholder replaced by its measurement; throws on an id the table lacks.
 * @param {string} template
 * @param {Table} table
 */
export function render(template, table) {
  return template.replace(PLACEHOLDER, (_, id, draws) => {
    const m = table.get(id);
    if (!m) throw new Error(`no measurement '${id}' in the table`);
    if (draws) {
      const range = m.seeds.match(/^(\d+)\.\.(\d+)$/);
      if (!range) throw new Error(`measurement ${id} is of one run ('${m.seeds}'), not a sample of draws`);
      return String(Number(range[2]) - Number(range[1]) + 1);
    }
    return shown(m, id);
  });
}

/**
 * The ids a template names, in order.
 * @param {string} template
 */
export const namedIn = (template) => [...template.matchAll(PLACEHOLDER)].map((m) => m[1]);

/**
 * The template with its placeholders removed: what must hold no number of its own.
 * @param {string} template
 */
export const withoutPlaceholders = (template) => template.replace(PLACEHOLDER, '⟨⟩');

/**
 * The fields of a lesson that a student reads.
 * @type {('title' | 'look' | 'question' | 'hint' | 'answer')[]}
 */
export const LESSON_TEXTS = ['title', 'look', 'question', 'hint', 'answer'];

/**
 * The Fluent variable of measurement `id` in a message file: `step.settle.min` is
 * `$step-settle-min`, and the number of its noise draws `$step-settle-min--draws` (ids hold no
 * hyphen, so the spelling reads back).
 * @param {string} id
 * @param {boolean} [draws]
 */
export const variableOf = (id, draws = false) => `${id.replaceAll('.', '-')}${draws ? '--draws' : ''}`;

/**
 * A message's text with its variables written back as placeholders ({ $a-b--draws } as {a.b#draws}),
 * so that a translated text is checked as the templates are.
 * @param {string} text
 */
export const placeholdersOf = (text) =>
  text.replace(/\{ ?\$([A-Za-z0-9_-]+) ?\}/g, (_, v) => `{${v.replace(/--draws$/, '#draws').replaceAll('-', '.')}}`);

/**
 * Every measurement of `table` that a text can state, as a message's variables, each shown in
 * `locale` as render() shows it.
 * @param {Table} table
 * @param {string} locale
 * @returns {Record<string, string | number>}
 */
export function measuredArgs(table, locale) {
  /** @type {Record<string, string | number>} */
  const args = {};
  for (const [id, m] of table) {
    if (Number.isFinite(m.value)) args[variableOf(id)] = shown(m, id, locale);
    const range = m.seeds.match(/^(\d+)\.\.(\d+)$/);
    if (range) args[variableOf(id, true)] = Number(range[2]) - Number(range[1]) + 1;
  }
  return args;
}
