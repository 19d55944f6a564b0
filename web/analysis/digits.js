// Numbers in the analysis and challenge tools' messages. The tools write their figures to a number
// of significant digits, as JavaScript writes them, and their counts without grouping (a seed, a
// count of runs or milliseconds reads as it does in the CLI's output): in English exactly so, in
// another language with its decimal separator and minus sign.
import { FluentNumber } from '@fluent/bundle';
import { language } from '../l10n/l10n.js';

/**
 * `text`, a number as JavaScript writes it, in the language shown: as it is in English, else with
 * the language's decimal separator and a minus sign for a negative.
 * @param {string} text
 */
function localized(text) {
  if (language === 'en') return text;
  const separator = new Intl.NumberFormat(language).formatToParts(0.5).find((p) => p.type === 'decimal')?.value ?? '.';
  return text.replace('.', separator).replace(/^-/, '−');
}

/**
 * `x` to `digits` significant digits, trailing zeros kept: 100.0 for 100 to four digits.
 * @param {number} x
 * @param {number} digits
 */
export const precise = (x, digits) => localized(x.toPrecision(digits));

/**
 * `x` to at most `digits` significant digits: 100 for 100 to four digits, 0.1235 for 0.123456.
 * @param {number} x
 * @param {number} digits
 */
export const sig = (x, digits) => localized(String(Number(x.toPrecision(digits))));

/**
 * A count (or a whole number of milliseconds) for a message, which may choose its plural form by it:
 * rounded to a whole number, its digits never grouped.
 * @param {number} n
 */
export const integer = (n) => new FluentNumber(n, { useGrouping: false, maximumFractionDigits: 0 });
