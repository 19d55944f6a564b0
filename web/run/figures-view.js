// The run's figures, all from the core: the strip of every figure with its unit, window and
// trend, the compact row of key figures, and the warnings they must not be read without.
import { ui } from '../ui/page.js';
import { el } from '../ui/dom.js';
import { local, percent, sig } from '../plots/numbers.js';
import { t } from '../l10n/l10n.js';

/** @import * as P from '../worker/protocol.js' */
/** @import { Plots } from '../plots/plots.js' */

/**
 * How a final value was still moving at the end of the run, a figure the run had not reached by
 * its end (in words, in place of its value), and what the figures must not be read without: the
 * core's `Trend`, `Unreached` and `Warning`.
 * @typedef {NonNullable<P.RunFigure['trend']>} Trend
 * @typedef {P.Spoken<P.Done>['unreached'][number]} Unreached
 * @typedef {P.Spoken<P.Done>['warnings'][number]} Warning
 */

/**
 * A value and its unit, if it has one.
 * @param {string} value
 * @param {string} unit
 */
const withUnit = (value, unit) => (unit ? `${value} ${unit}` : value);

// The figures the compact row shows, in this order.
const KEY_FIGURES = ['tracking_rms', 'current_peak', 'mean_nis', 'speed_error_final'];

/**
 * What the core derived from the figures: the peak and RMS currents as multiples of the rated
 * current, whether the mean NIS is inside its band.
 * @typedef {Pick<P.Done, 'peak_to_rated' | 'rms_to_rated' | 'nis_inside'>} Derived
 */

/**
 * The compact row of key figures that stands for the strip on small screens and projectors.
 * @param {P.RunFigure[]} figures
 * @param {Derived} derived
 */
function showKeyFigures(figures, { peak_to_rated: toRated, nis_inside: inside }) {
  const parts = KEY_FIGURES.map((name) => figures.find((f) => f.name === name))
    .filter((f) => f !== undefined)
    .map((f) => {
      const value = withUnit(sig(f.value, 3), f.unit);
      const span = document.createElement('span');
      if (f.name === 'current_peak' && toRated !== null)
        span.textContent = t('figures-key-peak', { value, ratio: sig(toRated, 2) });
      else if (f.name === 'speed_error_final' && f.trend) {
        span.textContent = t('figures-key-final', { value, trend: f.trend.state.replace(' ', '-') });
        if (!f.trend.settled) span.className = 'unsettled';
      } else if (f.name === 'mean_nis' && inside !== null) {
        const nis = sig(f.value, 4);
        span.textContent = t(inside ? 'figures-key-nis-inside' : 'figures-key-nis-outside', { value: nis });
      } else span.textContent = `${f.label} ${value}`;
      return span;
    });
  ui.keyFigures.replaceChildren(...parts.flatMap((p, i) => (i ? [' · ', p] : [p])));
  ui.figuresBar.hidden = parts.length === 0;
}

/**
 * Whether a final value `f` had settled, in words, from its trend over the end of the run:
 * [short text, the detail for its tooltip].
 * @param {P.RunFigure} f
 * @returns {[string, string]}
 */
function trendText(f) {
  const { rate, over, tolerance, scatter, to_go: toGo, state } = /** @type {Trend} */ (f.trend);
  /** @param {number} x @param {number} digits */
  const v = (x, digits) => withUnit(sig(x, digits), f.unit);
  const fit = t(toGo == null ? 'figures-trend-fit' : 'figures-trend-fit-approach', {
    ms: sig(over * 1e3, 3),
    rate: v(rate, 3),
    scatter: v(scatter, 2),
    'to-go': toGo == null ? '' : v(toGo, 2),
    tolerance: v(tolerance, 2),
  });
  if (state === 'settled') return [t('figures-trend-settled'), fit];
  if (state === 'ran away') return [t('figures-trend-ran-away'), fit];
  if (state === 'drifting') return [t('figures-trend-drifting'), fit];
  if (state === 'fluctuating') return [t('figures-trend-fluctuating', { scatter: v(scatter, 2) }), fit];
  if (toGo != null && toGo > tolerance)
    return [t('figures-trend-changing-to-go', { rate: v(rate, 2), 'to-go': v(toGo, 2) }), fit];
  return [t('figures-trend-changing', { rate: v(rate, 2) }), fit];
}

/**
 * An item of the strip for a figure the run had not reached by its end: the words, no value.
 * @param {Unreached} u
 * @returns {HTMLElement}
 */
function unreachedItem(u) {
  const item = el('div', { className: 'figure unsettled' });
  // As `imlab metrics` prints it: NAME_reached,0.
  Object.assign(item.dataset, { name: `${u.name}_reached`, value: '0' });
  item.append(
    el('dt', { textContent: u.label }),
    el('dd', { textContent: u.text, title: t('figures-no-value', { reason: u.text, window: u.window }) }),
    el('dd', { className: 'window', textContent: u.window }),
  );
  return item;
}

/** @type {Derived} */
const NONE = { peak_to_rated: null, rms_to_rated: null, nis_inside: null };

/**
 * The figures display; the plots in `plotSets` carry the figures in their text alternatives.
 * @param {{plotSets: Plots[]}} parts
 */
export function createFiguresView({ plotSets }) {
  /**
   * The figures strip: each figure of the run with its unit and window, and in place of a figure
   * the run had not reached by its end, the words that say so (all from the core).
   * @param {P.RunFigure[]} figures
   * @param {Warning[]} [warnings]
   * @param {Unreached[]} [unreached]
   * @param {Derived} [derived]
   */
  function show(figures, warnings = [], unreached = [], derived = NONE) {
    /** @param {P.RunFigure} f */
    const fmt = (f) => {
      if (f.name === 'saturated_share') return percent(f.value);
      if (f.unit === 's' && Math.abs(f.value) < 1) return `${sig(f.value * 1e3, 4)} ms`;
      return withUnit(sig(f.value, 4), f.unit);
    };
    const nis = Object.fromEntries(figures.filter((f) => f.name.startsWith('mean_nis')).map((f) => [f.name, f.value]));
    const rated = figures.find((f) => f.name === 'current_rated');
    const items = figures
      .flatMap((f, i) => [...unreached.filter((u) => u.index === i), f])
      .concat(unreached.filter((u) => u.index >= figures.length))
      .map((f) => {
        if (!('value' in f)) return unreachedItem(f);
        if (['mean_nis_low', 'mean_nis_high', 'current_rated'].includes(f.name)) return null;
        let text = fmt(f);
        const toRated = { current_peak: derived.peak_to_rated, current_rms: derived.rms_to_rated }[f.name] ?? null;
        if (rated && toRated !== null) {
          text = t('figures-to-rated', { value: text, ratio: sig(toRated, 3), rated: sig(rated.value, 4) });
        }
        if (f.name === 'mean_nis' && 'mean_nis_low' in nis && derived.nis_inside !== null) {
          text = t(derived.nis_inside ? 'figures-nis-inside' : 'figures-nis-outside', {
            value: text,
            low: sig(nis.mean_nis_low, 3),
            high: sig(nis.mean_nis_high, 3),
          });
        }
        const item = /** @type {HTMLElement} */ (el('div', { className: 'figure' }));
        item.dataset.name = f.name;
        item.dataset.value = String(f.value);
        // A value read at the last sample says whether the run had settled by then.
        const trend = f.trend && trendText(f);
        if (f.trend) {
          Object.assign(item.dataset, { rate: String(f.trend.rate), settled: f.trend.settled ? '1' : '0' });
          if (!f.trend.settled) item.classList.add('unsettled');
        }
        if (f.name === 'mean_nis')
          Object.assign(item.dataset, { low: String(nis.mean_nis_low), high: String(nis.mean_nis_high) });
        if (f.name === 'current_peak' && rated) item.dataset.rated = String(rated.value);
        item.append(
          el('dt', { textContent: f.label }),
          el('dd', {
            textContent: text,
            title: t('figures-exact', { value: withUnit(local(String(f.value)), f.unit), window: f.window }),
          }),
          el('dd', { className: 'window', textContent: f.window }),
        );
        if (trend) item.append(el('dd', { className: 'trend', textContent: trend[0], title: trend[1] }));
        return item;
      })
      .filter((item) => item !== null);
    // What the figures must not be read without, in the core's words.
    // (A run that ran away says so in the message above, as a failure.)
    const warning = warnings
      .filter((w) => w.kind !== 'runaway')
      .map((w) => w.text)
      .join(' ');
    ui.consistency.textContent = warning;
    ui.consistency.hidden = !warning;
    ui.figures.replaceChildren(...items);
    ui.figures.hidden = items.length === 0;
    showKeyFigures(figures, derived);
    // The plots' text alternatives carry the same figures.
    const sentence = items
      // Every item has its label (dt) and its value or words (dd).
      .map(
        (item) =>
          `${/** @type {HTMLElement} */ (item.querySelector('dt')).textContent} ${/** @type {HTMLElement} */ (item.querySelector('dd')).textContent}`,
      )
      .join('; ');
    for (const set of plotSets)
      set.describe(sentence ? [t('figures-caption', { figures: sentence }), warning].filter(Boolean).join(' ') : '');
  }

  ui.figuresToggle.addEventListener('click', () => {
    const open = !ui.figures.classList.contains('open');
    ui.figures.classList.toggle('open', open);
    ui.figuresToggle.setAttribute('aria-expanded', String(open));
    ui.figuresToggle.textContent = t(open ? 'figures-fewer' : 'figures-all');
  });

  return { show };
}
