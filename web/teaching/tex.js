// The walkthrough's equations: our own TeX typeset by KaTeX, and the plain-text reading of a short
// label for screen readers. KaTeX, its stylesheet and its fonts are fetched when an equation is
// first shown (the walkthrough opened, a sample inspected), not with the page: the first plot
// needs none of them.
import { el } from '../ui/dom.js';

/** KaTeX once loaded, else null. @type {typeof import('../../vendor/katex/katex.mjs').default | null} */
let katex = null;
/** @type {Promise<void> | null} */
let loading = null;

/** Fetches KaTeX and its stylesheet, once; resolves when both are in. */
export function loadTex() {
  if (loading) return loading;
  const link = el('link', { rel: 'stylesheet', href: 'vendor/katex/katex.min.css' });
  loading = Promise.all([
    import('../../vendor/katex/katex.mjs'),
    new Promise((resolve, reject) => {
      link.addEventListener('load', resolve);
      link.addEventListener('error', () => reject(new Error('the equations’ stylesheet could not be loaded')));
      document.head.append(link);
    }),
  ]).then(
    ([module]) => {
      katex = module.default;
    },
    (e) => {
      // Tried again when an equation is next shown.
      link.remove();
      loading = null;
      throw e;
    },
  );
  return loading;
}

/** A KaTeX-rendered equation (our own TeX, never text from the URL). `label`, if given, is its
 * plain-text name for screen readers (a table header needs one: axe does not read MathML). Until
 * KaTeX is in, the span shows the plain-text reading.
 * @param {string} source
 * @param {boolean} [displayMode]
 * @param {string | null} [label]
 */
export function tex(source, displayMode = true, label = null) {
  const span = el('span', { className: displayMode ? 'equation' : 'math', textContent: plain(source) });
  const done = () => {
    typeset(span, source, displayMode);
    if (label) {
      // None where KaTeX could not read the TeX: it shows the error instead.
      const math = span.querySelector('.katex');
      math?.setAttribute('role', 'math');
      math?.setAttribute('aria-label', label);
    }
  };
  if (katex) done();
  else loadTex().then(done, () => {});
  return span;
}

/**
 * Typesets our TeX `source` into `span`, once KaTeX is in. A display equation is set in display
 * style but as KaTeX's inline math, which may break after a top-level relation, operator or wide
 * space: a line too long for a phone wraps there, rather than scroll sideways or be cut.
 * @param {HTMLElement} span
 * @param {string} source
 * @param {boolean} displayMode
 */
function typeset(span, source, displayMode) {
  // A wide space parts two equations of a line, or an equation and its number: it may break too.
  const text = displayMode ? `\\displaystyle ${source.replace(/\\q?quad\b/g, '$&\\allowbreak ')}` : source;
  /** @type {NonNullable<typeof katex>} */ (katex).render(text, span, {
    displayMode: false,
    throwOnError: false,
    strict: 'ignore',
  });
}

/**
 * A display equation typeset when it is first shown (see `Walkthrough.shown`).
 * @param {string} source
 */
export function laterTex(source) {
  const span = el('span', { className: 'equation' });
  span.dataset.tex = source;
  return span;
}

/**
 * Typesets the equations made by `laterTex` inside `container`, once KaTeX is in.
 * @param {HTMLElement} container
 */
export async function typesetWaiting(container) {
  await loadTex();
  for (const span of /** @type {NodeListOf<HTMLElement>} */ (container.querySelectorAll('.equation[data-tex]'))) {
    typeset(span, /** @type {string} */ (span.dataset.tex), true);
    delete span.dataset.tex;
  }
}

/**
 * A plain-text reading of a short TeX label: "a_1(x_3\\hat x_4 - x_2\\hat x_5)" → "a1(x3x̂4 − x2x̂5)".
 * @param {string} source
 */
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
