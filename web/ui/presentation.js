// How the page is laid out for an audience: presentation mode (larger text and plots, kept in
// the link as `#present=1`), the settings drawer it and small screens use, and an embed
// (`#embed=PLOT,PLOT...`) that shows a few plots in a frame of any size.
import { $, say, ui } from './page.js';
import { fragment, setFragment } from './url.js';
import { excerpt } from './quote.js';
import { t } from '../l10n/l10n.js';

const PLOT_HEIGHT = { normal: [260, 220], present: [380, 320] };
// The least height of an embedded chart, however small its frame (px): a plot area of about
// 110 px under its time axis; a smaller frame scrolls rather than squash the plots.
const EMBED_MIN_HEIGHT = 200;
const EMBED_MARGIN = 8;
// Presentation mode draws plot text and lines this much larger: 14 px ticks become 21 px.
const PRESENT_SCALE = 1.5;
// In presentation mode the main plots are as tall as PLOT_HEIGHT.present allows and the first
// screen holds, down to this least height (px), with this margin under the first plot.
const PRESENT_MIN_HEIGHT = 260;
const PRESENT_MARGIN = 8;
// The widths a lesson's column may take beside the results in presentation mode (rem), narrowest
// first, up to at most this share of the window, so that the plot keeps the rest; and the sizes
// its question may be set in (rem), largest first, down to 24 px, which a projected room reads.
const QUESTION_WIDTHS = [15, 17, 19, 21, 23, 25, 27, 29, 31, 33, 35];
const QUESTION_MAX_SHARE = 0.55;
const QUESTION_SIZES = [1.25, 1.2];

/**
 * In presentation mode, sets an open lesson's question in the largest of QUESTION_SIZES, and its
 * column in the narrowest of QUESTION_WIDTHS, that hold its title, question and buttons without
 * scrolling (what to look for, the hint and the answer scroll in their own boxes); its height is
 * the window's below where the results begin.
 */
function fitQuestion() {
  const results = /** @type {HTMLElement} */ (document.querySelector('.results'));
  const panel = document.getElementById('lesson-panel');
  if (!panel || panel.hidden) return;
  results.style.setProperty('--lesson-top', `${Math.round(results.getBoundingClientRect().top + scrollY)}px`);
  const rem = parseFloat(getComputedStyle(document.documentElement).fontSize);
  const widths = QUESTION_WIDTHS.filter((w, i) => i === 0 || w * rem <= QUESTION_MAX_SHARE * innerWidth);
  for (const size of QUESTION_SIZES) {
    results.style.setProperty('--question-size', `${size}rem`);
    for (const w of widths) {
      results.style.setProperty('--lesson-width', `${w}rem`);
      if (panel.scrollHeight <= panel.clientHeight) return;
    }
  }
}

/**
 * Sets up the layout the link asks for; `fitEmbed()` sizes an embed's plots to its frame.
 * `state.notice` is a notice about the link that stays until the user acts; `rescaled()` follows
 * a change of the plots' scale (presentation mode switched).
 * @param {{state: {notice: string | null}, plots: import('../plots/plots.js').Plots,
 *   walkthrough: import('../teaching/walkthrough.js').Walkthrough, rescaled: () => void}} parts
 */
export function createPresentation({ state, plots, walkthrough, rescaled }) {
  /** @type {(() => void) | null} sizes the embedded plots to the frame, in an embed */
  let fitEmbed = null;

  /**
   * Presentation mode: larger text and plots, settings in the drawer; kept in the URL fragment.
   * @param {boolean} on
   */
  function present(on) {
    document.body.classList.toggle('present', on);
    ui.present.setAttribute('aria-pressed', String(on));
    setFragment('present', on ? '1' : null);
    const [main, small] = PLOT_HEIGHT[on ? 'present' : 'normal'];
    const scale = on ? PRESENT_SCALE : 1;
    plots.rescale(scale, main);
    walkthrough.plots.rescale(scale, small);
    rescaled();
    openSettings(false);
    fitPresent();
  }

  /**
   * In presentation mode, fits an open lesson's column (fitQuestion), then sizes the main plots
   * so that the first one shown (a lesson's own plot, which the style puts first), with its title,
   * axes and legend, ends on the first screen: what stands above it (the run bar, the tabs, the
   * key figures) is measured as laid out.
   */
  function fitPresent() {
    const body = document.body.classList;
    if (!body.contains('present') || body.contains('embed')) return;
    fitQuestion();
    const first = ui.plots.querySelector('.plot.lesson-plot') ?? ui.plots.querySelector('.plot');
    if (!first || $('panel-plots', HTMLDivElement).hidden) return;
    const box = first.getBoundingClientRect();
    const rest = box.height - plots.height; // the title and the legend
    const room = Math.floor(innerHeight - (box.top + scrollY) - rest - PRESENT_MARGIN);
    const height = Math.max(PRESENT_MIN_HEIGHT, Math.min(PLOT_HEIGHT.present[0], room));
    const chart = first.querySelector('canvas');
    // A chart drawn before its column narrowed is sized to the new width too.
    if (height !== plots.height || (chart && Math.abs(chart.clientWidth - plots.width()) > 1)) plots.resize(height);
  }
  // What stands above the plots changes height as a run ends (its key figures), a lesson opens
  // (the columns narrow) or the window changes: each time the plots are sized again.
  const above = new ResizeObserver(() => fitPresent());
  for (const e of document.querySelectorAll(
    '.run-bar, .tab-row, .view-bar, .figures-bar, #message, #consistency, #panel-plots, #lesson-panel',
  ))
    above.observe(e);
  // A lesson opened, or the next one, brings its own question: its column is fitted again.
  new MutationObserver(() => fitPresent()).observe($('lesson-panel'), { childList: true });
  window.addEventListener('resize', fitPresent);
  ui.present.addEventListener('click', () => present(!document.body.classList.contains('present')));

  /**
   * Opens or closes the settings drawer (presentation mode and small screens).
   * @param {boolean} open
   */
  function openSettings(open) {
    document.body.classList.toggle('settings-open', open);
    ui.settingsToggle.setAttribute('aria-expanded', String(open));
  }
  ui.settingsToggle.addEventListener('click', () => openSettings(!document.body.classList.contains('settings-open')));

  /**
   * Height of each of `n` embedded plots: together they fill the frame under the run row. What is
   * not plot (the run row, the key figures, titles and legends) is measured from the page as laid
   * out, down to the last plot's bottom and a margin.
   * @param {number} n
   */
  function embedHeight(n) {
    const shown = [...ui.plots.querySelectorAll('.plot.embedded')];
    if (shown.length === 0) return plots.height;
    const bottom = Math.max(...shown.map((p) => p.getBoundingClientRect().bottom)) + scrollY + EMBED_MARGIN;
    return Math.max(EMBED_MIN_HEIGHT, Math.floor(plots.height + (innerHeight - bottom) / n));
  }

  // An embed (`#embed=PLOT,PLOT...`) shows those plots of the Trajectories tab with Run and the key
  // figures, the plots sharing the frame's height, so that the frame holds them at any size.
  const embedded = fragment('embed');
  if (embedded !== null) {
    const all = plots.defs.map((p) => p.id);
    const asked = embedded.split(',').slice(0, all.length);
    const ids = asked.filter((id) => all.includes(id));
    const unknown = asked.filter((id) => !ids.includes(id));
    if (ids.length === 0) ids.push('speed');
    document.body.classList.add('embed');
    document.body.dataset.embed = ids.join(',');
    plots.embedded = ids;
    for (const div of /** @type {NodeListOf<HTMLElement>} */ (ui.plots.querySelectorAll('.plot[data-plot]')))
      div.classList.toggle('embedded', ids.includes(/** @type {string} */ (div.dataset.plot)));
    // Kept until the user acts: a load's message would otherwise clear it.
    if (unknown.length)
      state.notice = t('embed-unknown-plots', {
        names: unknown.map((id) => `'${excerpt(id)}'`).join(', '),
        count: unknown.length,
        shown: ids.join(', '),
        plots: all.join(', '),
      });
    say(state.notice ?? '', 'info');
    fitEmbed = () => plots.resize(embedHeight(ids.length));
    window.addEventListener('resize', fitEmbed);
  }
  if (fragment('present') === '1') {
    document.body.classList.add('present');
    ui.present.setAttribute('aria-pressed', 'true');
    plots.scale = walkthrough.plots.scale = PRESENT_SCALE;
    [plots.height, walkthrough.plots.height] = PLOT_HEIGHT.present;
  }

  return { openSettings, fitEmbed: () => fitEmbed?.() };
}
