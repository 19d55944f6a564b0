// The language menu in the header: the page speaks the language chosen, and every link it writes
// names it (`lang=` in the fragment), so a class opens a lecturer's link in the lecturer's language.
import { LANGUAGES, language } from '../l10n/l10n.js';
import { $ } from './page.js';
import { fragment, setFragment } from './url.js';

/**
 * `href` with the language shown named in its fragment (`#…&lang=de`), unless it names one.
 * @param {string} href
 */
export function withLanguage(href) {
  const url = new URL(href);
  const entries = url.hash.slice(1).split('&').filter(Boolean);
  if (entries.some((e) => e.startsWith('lang='))) return href;
  url.hash = [...entries, `lang=${language}`].join('&');
  return url.href;
}

/**
 * Fills the menu (choosing a language reloads the page in it, with the address's run) and points
 * the student guide's links at its translation.
 */
export function wireLanguageMenu() {
  if (language !== 'en')
    for (const link of document.querySelectorAll('a[href="docs/student-guide.html"]'))
      link.setAttribute('href', `docs/${language}/student-guide.html`);
  const menu = $('language', HTMLSelectElement);
  menu.replaceChildren(...LANGUAGES.map(([code, name]) => new Option(name, code, false, code === language)));
  menu.addEventListener('change', () => {
    if (menu.value === (fragment('lang') ?? language)) return;
    setFragment('lang', menu.value);
    location.reload();
  });
}
