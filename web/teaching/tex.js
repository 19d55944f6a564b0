// The walkthrough's equations: our own TeX typeset by KaTeX, now or while the page is idle, and
// the plain-text reading of a short label for screen readers.
import katex from '../../vendor/katex/katex.mjs';
import { el } from '../ui/dom.js';

/** A KaTeX-rendered equation (our own TeX, never text from the URL). `label`, if given, is its
 * plain-text name for screen readers (a table header needs one: axe does not read MathML). */
export function tex(source, displayMode = true, label = null) {
  const span = el('span', { className: displayMode ? 'equation' : 'math' });
  typeset(span, source, displayMode);
  if (label) {
    const math = span.querySelector('.katex');
    math.setAttribute('role', 'math');
    math.setAttribute('aria-label', label);
  }
  return span;
}

/** Typesets our TeX `source` into `span`. */
function typeset(span, source, displayMode) {
  katex.render(source, span, { displayMode, throwOnError: false, strict: 'ignore' });
}

/** A display equation typeset later, while the page is idle or when the walkthrough is first
 * shown (see `Walkthrough.typesetWhenIdle` and `Walkthrough.shown`): typesetting all of them
 * takes KaTeX longer than anything else at page load. */
export function laterTex(source) {
  const span = el('span', { className: 'equation' });
  span.dataset.tex = source;
  return span;
}

/** Typesets an equation made by `laterTex`. */
export function typesetWaiting(span) {
  typeset(span, span.dataset.tex, true);
  delete span.dataset.tex;
}

/** A plain-text reading of a short TeX label: "a_1(x_3\\hat x_4 - x_2\\hat x_5)" → "a1(x3x̂4 − x2x̂5)". */
export function plain(source) {
  return source
    .replace(/\\hat ([a-z])/g, '$1\u0302')
    .replace(/\\psi/g, 'ψ')
    .replace(/\\omega/g, 'ω')
    .replace(/\\cdot/g, '·')
    .replace(/\\text\{([^}]*)\}/g, '$1')
    .replace(/\\ /g, ' ')
    .replace(/ - /g, ' − ')
    .replace(/[_{}^]/g, '');
}
