// The model-error map's colour scale, and the number format of its cells and axes.
import { t } from '../l10n/l10n.js';
import { sig } from './digits.js';

/**
 * A number for a cell or an axis tick: four significant digits.
 * @param {number} v
 */
export const fmt = (v) => (Number.isFinite(v) ? sig(v, 4) : '—');

// Colours of the heat map: light to dark for values of one sign (readable in greyscale), and
// blue through white to red for values of both signs, white at zero.
const SCALE = ['#f7fbff', '#deebf7', '#c6dbef', '#9ecae1', '#6baed6', '#4292c6', '#2171b5', '#08519c', '#08306b'];
const DIVERGING = ['#2166ac', '#4393c3', '#92c5de', '#d1e5f0', '#f7f7f7', '#fddbc7', '#f4a582', '#d6604d', '#b2182b'];

/**
 * A colour scale: `of(v)` is the colour of `v` and whether its text is light; `words` says the
 * scale and its ends.
 * @typedef {{of: (v: number) => [string, boolean], words: string}} ColourScale
 */

/**
 * The colour of `v` among `values`: values of both signs on a scale centred at zero; values of
 * one sign on a log scale when they span more than a decade, else linear. Returns {of(v) →
 * [colour, light text], words: the scale and its ends}.
 * @param {number[]} values
 * @returns {ColourScale}
 */
export function colourScale(values) {
  const finite = values.filter(Number.isFinite);
  const [min, max] = [Math.min(...finite), Math.max(...finite)];
  /**
   * @param {string[]} palette
   * @param {number} x
   * @returns {[string, boolean]}
   */
  const pick = (palette, x) => {
    const i = Math.min(palette.length - 1, Math.max(0, Math.round(x * (palette.length - 1))));
    return [palette[i], palette === SCALE ? i >= 5 : i <= 1 || i >= 7];
  };
  if (min < 0 && max > 0) {
    const m = Math.max(-min, max);
    return { of: (v) => pick(DIVERGING, 0.5 + v / (2 * m)), words: t('map-scale-diverging', { max: fmt(m) }) };
  }
  const log = min > 0 && max / min > 10;
  /** @type {(v: number) => number} */
  const f = log ? Math.log10 : (v) => v;
  const [lo, hi] = [f(min), f(max)];
  return {
    of: (v) => pick(SCALE, hi > lo ? (f(v) - lo) / (hi - lo) : 0.5),
    words: t(log ? 'map-scale-log' : 'map-scale-linear', { min: fmt(min), max: fmt(max) }),
  };
}
