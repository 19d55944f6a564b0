// How numbers read on the page: counts and measured values in its sentences, in the language
// shown; on a plot, the legend's read-out, and the axes' tick steps, tick labels and the room time
// ticks need; the same on every chart.
import { language } from '../l10n/l10n.js';

/**
 * A number as JavaScript writes it (`text`, from String() or toFixed()), in the language shown: its
 * decimal point and leading minus the language's. English keeps it as written.
 * @param {string} text
 */
export function local(text) {
  if (language === 'en') return text;
  const parts = new Intl.NumberFormat(language).formatToParts(1.5);
  const point = parts.find((p) => p.type === 'decimal')?.value ?? '.';
  return text.replace('.', point).replace(/^-/, '−');
}

/**
 * `value` to `digits` significant digits, as the page's sentences write a measured value: 0.01234
 * to three is "0.0123" (no trailing zeros).
 * @param {number} value
 * @param {number} digits
 */
export const sig = (value, digits) => local(String(Number(value.toPrecision(digits))));

/**
 * `value` with `digits` decimals, as the page's sentences write it.
 * @param {number} value
 * @param {number} digits
 */
export const fixed = (value, digits) => local(value.toFixed(digits));

/**
 * A whole number as the page's sentences write it: in English, thousands grouped by commas; in
 * another language, as the language groups them.
 * @param {number} n
 */
export const count = (n) =>
  language === 'en' ? String(n).replace(/\B(?=(\d{3})+(?!\d))/g, ',') : new Intl.NumberFormat(language).format(n);

/**
 * A share (0 to 1) as a percentage of three significant figures, as the figures strip writes the
 * share of samples at the voltage limit: 0.0123 is "1.23 %", none is "0 %".
 * @param {number} share
 */
export const percent = (share) => `${sig(share * 100, 3)} %`;

// Tick steps of 1, 2 and 5 times a power of ten: a step of 2.5 would cost every label one more digit.
export const STEPS = Array.from({ length: 33 }, (_, i) => i - 16).flatMap((e) =>
  [1, 2, 5].map((m) => Number(`${m}e${e}`)),
);

/**
 * Decimals that write `step` exactly (0.25 needs 2, 200 needs none).
 * @param {number} step
 */
function decimals(step) {
  for (let d = 0; d < 20; d++) {
    const m = step * 10 ** d;
    if (Math.round(m) >= 1 && Math.abs(m - Math.round(m)) < 1e-6 * m) return d;
  }
  return 20;
}

// Values this far from 1 read better as powers of ten than as long runs of zeros.
const SMALL = 1e-3;
const LARGE = 1e6;

/**
 * Tick labels with the digits their spacing needs, so that neighbouring ticks never read alike
 * at any zoom; tiny and huge values as powers of ten. A log axis's ticks are each one digit times
 * a power of ten, so three significant digits write every one of them.
 * @param {uPlot} u
 * @param {(number | null)[]} splits
 * @param {number} axisIdx
 * @param {number} space
 * @param {number} step
 * @returns {string[]}
 */
export function tickLabels(u, splits, axisIdx, space, step) {
  // uPlot gives every axis its scale.
  if (u.scales[/** @type {string} */ (u.axes[axisIdx].scale)].distr === 3 || !(step > 0)) {
    return splits.map((v) => (v == null ? '' : String(Number(v.toPrecision(3)))));
  }
  // A tick that should be zero often misses it by a rounding error, which would print as −0.
  const ticks = splits.map((v) => (v == null ? null : Math.abs(v) < step * 1e-6 ? 0 : v));
  const largest = Math.max(...ticks.map((v) => Math.abs(v ?? 0)));
  const d = decimals(step);
  if (largest === 0 || (largest >= SMALL && largest < LARGE)) return ticks.map((v) => (v == null ? '' : v.toFixed(d)));
  return ticks.map((v) => {
    if (v == null) return '';
    if (v === 0) return '0';
    const digits = Math.min(Math.max(Math.floor(Math.log10(Math.abs(v))) + d, 0), 20);
    return v
      .toExponential(digits)
      .replace(/\.?0+e/, 'e')
      .replace('e+', 'e');
  });
}

/**
 * The least room between time ticks (px), `least` or more: room for a label with the window's
 * whole digits and the decimals of the finest step `least` allows, and a gap of one `em` (the
 * font size, px), so that the long labels of a narrow window do not run into each other.
 * @param {number} em
 * @param {number} least
 * @returns {(u: uPlot, axisIdx: number, lo: number, hi: number, dim: number) => number}
 */
export const timeSpace = (em, least) => (u, axisIdx, lo, hi, dim) => {
  const step = ((hi - lo) * least) / dim;
  if (!(step > 0)) return least;
  const chars = String(Math.trunc(Math.max(Math.abs(lo), Math.abs(hi)))).length + 1 - Math.floor(Math.log10(step));
  return Math.max(least, (chars * 0.6 + 1) * em);
};

/**
 * A value as the read-out shows it: 6 significant digits.
 * @param {number | null | undefined} v
 */
export const six = (v) => (v == null ? '–' : String(Number(v.toPrecision(6))));

/**
 * Chart options `opts` with numbers written as the page writes them on every axis and in every
 * read-out of the legend, where the chart gives no formatter of its own: the trajectory plots'
 * tick labels and six significant digits, rather than uPlot's (which follow the browser's locale).
 * @param {uPlot.Options} opts
 * @returns {uPlot.Options}
 */
export function pageNumbers(opts) {
  for (const axis of opts.axes ?? []) axis.values ??= tickLabels;
  for (const series of opts.series) series.value ??= (u, v) => six(v);
  return opts;
}
