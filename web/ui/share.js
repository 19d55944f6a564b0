// The links the page hands out: the address of this run, and an embed code for the plots in view.
import { say, ui } from './page.js';
import { t } from '../l10n/l10n.js';
import { withLanguage } from './language.js';

/** The Trajectories plots the user is looking at: those at least half in view, else the speed plot. */
function plotsInView() {
  if (ui.plots.offsetParent === null) return ['speed'];
  const inView = [.../** @type {NodeListOf<HTMLElement>} */ (ui.plots.querySelectorAll('.plot[data-plot]'))]
    .filter((p) => {
      const box = p.getBoundingClientRect();
      const shown = Math.min(box.bottom, innerHeight) - Math.max(box.top, 0);
      return box.height > 0 && shown >= box.height / 2;
    })
    .map((p) => /** @type {string} */ (p.dataset.plot));
  return inView.length ? inView : ['speed'];
}

/**
 * Wires Copy link and Copy embed code. `state.info` is the core's description of the scenario in
 * the form, null until the first one comes.
 * @param {{state: {info: import('../worker/protocol.js').Info | null}}} parts
 */
export function wireShare({ state }) {
  ui.copy.addEventListener('click', async () => {
    try {
      await navigator.clipboard.writeText(withLanguage(location.href));
      say(t('share-link-copied'), 'info');
    } catch {
      say(t('share-copy-this-link', { link: withLanguage(location.href) }), 'info');
    }
  });

  ui.embed.addEventListener('click', async () => {
    const info = state.info;
    if (!info) return; // no scenario described yet: nothing to embed
    const ids = plotsInView();
    const src = withLanguage(`${location.origin}${location.pathname}?${info.encoded}#embed=${ids.join(',')}`);
    const title = t('share-embed-title', { preset: info.preset, plots: ids.join(', ') }).replace(
      /[&<"]/g,
      (c) => `&#${c.charCodeAt(0)};`,
    );
    // The plots share whatever height the frame has; this one gives each about 300 px.
    const height = 140 + 300 * ids.length;
    const code = `<iframe src="${src.replaceAll('"', '%22')}" title="${title}" width="100%" height="${height}" style="border:0;max-width:960px" loading="lazy"></iframe>`;
    const what = { plots: ids.join(', '), count: ids.length };
    try {
      await navigator.clipboard.writeText(code);
      say(t('share-embed-copied', what), 'info');
    } catch {
      say(t('share-embed-copy-this', { ...what, code }), 'info');
    }
  });
}
