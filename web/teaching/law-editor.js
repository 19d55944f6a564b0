// "Write this step": a step's own law in the walkthrough. Its editor is the settings form's field
// (law.v1..law.v4) as a knob; the formula is typeset by the core's TeX as it is typed, an error is
// marked at its place, and after a run the core's verdict says whether the law gives the step's
// designed dynamics. The names the law may use come from the core too. Its words are messages of
// the rest (teaching-page.ftl); the core's (why a formula is refused, the verdict, what each name
// means) come as its messages (core-formula.ftl, core-law.ftl), said as the worker's reply arrives.
import { el } from '../ui/dom.js';
import { num, t } from '../l10n/l10n.js';
import { paperLaw, verdictLine } from '../ui/verdict-line.js';
import { tex } from './tex.js';

/** @typedef {import('../worker/protocol.js').Jobs} Jobs */

/**
 * The block of step `step` (1–4): its explanation (`intro`), the knob's box, the preview, the
 * verdict and the names it may use.
 * @param {number} step
 * @param {string} intro
 */
export function lawBlock(step, intro) {
  const box = el('div', { className: 'law' });
  box.dataset.step = String(step);
  box.dataset.lawScope = '';
  const knobs = el('div', { className: 'knobs' });
  knobs.dataset.keys = `law.v${step}`;
  box.append(
    el('h3', { textContent: t('law-write') }),
    el('p', { textContent: intro }),
    knobs,
    el('div', { className: 'law-preview', id: `law-preview-${step}` }),
    verdictLine(step),
    el('details', { className: 'law-names' }, [el('summary', { textContent: t('law-names') })]),
  );
  return box;
}

/**
 * Shows the core's `preview` of `text` in `box`: the law typeset, or the error with the part of the
 * formula it concerns marked (the core counts characters from 1; 0 is the formula as a whole).
 * @param {HTMLElement} box
 * @param {Jobs['law-preview']['result']} preview
 * @param {string} text
 */
export function showPreview(box, preview, text) {
  const out = /** @type {Element} */ (box.querySelector('.law-preview'));
  const input = box.querySelector('input.formula');
  input?.setAttribute('aria-describedby', out.id);
  input?.setAttribute('aria-invalid', String(!!preview.error && text.trim() !== ''));
  if (text.trim() === '') {
    out.replaceChildren();
    return;
  }
  if (preview.tex) {
    out.replaceChildren(tex(preview.tex, true, `v${box.dataset.step} = ${text}`));
    return;
  }
  // The core gives the TeX or the error.
  const { at, len, reason } = /** @type {NonNullable<typeof preview.error>} */ (preview.error);
  const chars = [...text];
  const parts =
    at === 0
      ? [chars.join('')]
      : [
          chars.slice(0, at - 1).join(''),
          el('mark', { textContent: chars.slice(at - 1, at - 1 + len).join('') || ' ' }),
          chars.slice(at - 1 + len).join(''),
        ];
  out.replaceChildren(
    el('p', { className: 'law-error', textContent: at === 0 ? reason : t('law-error-at', { at: num(at), reason }) }),
    el('code', { className: 'law-text' }, parts),
  );
}

/**
 * The formula typed for step `step` under `root`: the input beside its verdict line.
 * @param {ParentNode} root
 * @param {number} step
 */
function typedLaw(root, step) {
  const line = root.querySelector(`.law-verdict[data-law-step="${step}"]`);
  const input = line?.closest('[data-law-scope]')?.querySelector('input.formula');
  return input instanceof HTMLInputElement ? input.value.trim() : null;
}

/**
 * Shows in every verdict line under `root` its step's verdict (the core's, for the run shown), or
 * that the step is the paper's. A verdict on a law other than the one now typed beside it (edited
 * since, or not parsed), or judged on an earlier step's own law that has been edited since, is
 * shown as the last run's, with the law it is about, and neither good nor bad: it does not
 * describe what is typed. A line is written only when it changes, so that a screen reader
 * announces a change and not each key typed.
 * @param {ParentNode} root
 * @param {Jobs['law-verdicts']['result']} verdicts
 */
export function showVerdicts(root, verdicts) {
  for (const line of /** @type {NodeListOf<HTMLElement>} */ (root.querySelectorAll('.law-verdict'))) {
    const step = Number(line.dataset.lawStep);
    const verdict = verdicts.find((v) => v.step === step);
    const edited = (/** @type {number} */ s, /** @type {string} */ law) => {
      const typed = typedLaw(root, s);
      return typed !== null && typed !== law.trim();
    };
    const stale = !!verdict && (edited(step, verdict.law) || (verdict.on !== null && edited(step - 1, verdict.on)));
    const text = !verdict ? paperLaw(step) : stale ? staleText(step, verdict) : verdict.text;
    if (line.textContent !== text) line.textContent = text;
    line.classList.toggle('stale', stale);
    line.classList.toggle('good', !stale && verdict?.designed === true);
    line.classList.toggle('bad', !stale && verdict?.designed === false);
  }
}

/**
 * The verdict `verdict` on step `step`'s law, said to be of a law other than the one typed.
 * @param {number} step
 * @param {Jobs['law-verdicts']['result'][number]} verdict
 */
function staleText(step, verdict) {
  const args = { output: `v${step}`, law: verdict.law, verdict: verdict.text };
  return verdict.on === null
    ? t('law-stale', args)
    : t('law-stale-after', { ...args, previous: `v${step - 1}`, previousLaw: verdict.on });
}

/**
 * Says in each verdict line under `root` whose step has a law typed: `text`.
 * @param {ParentNode} root
 * @param {string} text
 */
export function sayOfTypedLaws(root, text) {
  for (const line of /** @type {NodeListOf<HTMLElement>} */ (root.querySelectorAll('.law-verdict'))) {
    const typed = line.closest('[data-law-scope]')?.querySelector('input.formula');
    if (typed instanceof HTMLInputElement && typed.value.trim()) {
      line.textContent = text;
      line.classList.remove('good', 'bad', 'stale');
    }
  }
}

/**
 * Lists in each step's block the names its law may use (`language`, the core's) and the functions,
 * each with its meaning in the language shown.
 * @param {HTMLElement} container
 * @param {Jobs['law-language']['result']} language
 */
export function fillNames(container, language) {
  for (const box of /** @type {NodeListOf<HTMLElement>} */ (container.querySelectorAll('.law'))) {
    const step = Number(box.dataset.step);
    const details = /** @type {HTMLDetailsElement} */ (box.querySelector('.law-names'));
    const rows = language.names
      .filter((n) => n.from_step <= step)
      .map((n) =>
        el('tr', {}, [
          el('td', {}, [el('code', { textContent: n.name })]),
          el('td', {}, [tex(n.tex, false, n.name)]),
          el('td', { textContent: n.unit }),
          el('td', { textContent: n.doc }),
        ]),
      );
    const head = el('tr', {}, [
      el('th', { scope: 'col', textContent: t('law-names-name') }),
      el('th', { scope: 'col', textContent: t('law-names-symbol') }),
      el('th', { scope: 'col', textContent: t('law-names-unit') }),
      el('th', { scope: 'col', textContent: t('law-names-meaning') }),
    ]);
    const functions = language.functions.map((f) => f.doc).join('; ');
    details.replaceChildren(
      /** @type {HTMLElement} */ (details.querySelector('summary')),
      el('div', { className: 'table-scroll' }, [el('table', {}, [head, ...rows])]),
      el('p', { textContent: t('law-names-functions', { functions }) }),
    );
  }
}
