// The page's words in the reader's language: Fluent messages (web/locales/LANG/*.ftl), the language
// negotiated from the link's `lang=` and the browser's preferences, numbers formatted for the
// language. Links, CSV and scenario keys stay language-neutral: only what is shown is translated.
import { FluentBundle, FluentNumber, FluentResource } from '@fluent/bundle';
import { negotiateLanguages } from '@fluent/langneg';
import { FILES } from './catalog.js';
import { LANGUAGES } from './languages.js';
import { isCoreMessage } from './core-message.js';

export { LANGUAGES };

const CODES = LANGUAGES.map(([code]) => code);

/**
 * The language a page opened with `fragmentLang` (the link's `lang=`, or null) speaks: the link's,
 * when the page speaks it, else the first of the browser's preferred languages it speaks, else
 * English.
 * @param {string | null} fragmentLang
 * @param {readonly string[]} preferred
 */
export function chooseLanguage(fragmentLang, preferred) {
  const asked = fragmentLang === null ? [] : [fragmentLang];
  return negotiateLanguages([...asked, ...preferred], CODES, { strategy: 'lookup', defaultLocale: 'en' })[0];
}

/** The language shown. */
export let language = 'en';
let bundle = new FluentBundle('en', { useIsolating: false });
/** @type {Map<string, Promise<void>>} */
const loading = new Map();

/**
 * Adds an FTL text to `target`'s messages; a message file that does not parse is the page's mistake.
 * @param {FluentBundle} target
 * @param {string} text
 * @param {string} name
 */
function add(target, text, name) {
  const errors = target.addResource(new FluentResource(text));
  if (errors.length) throw new Error(`${name}: ${errors.map(String).join('; ')}`);
}

/**
 * Speaks `lang` from now on: fetches its page messages.
 * @param {string} lang
 */
export async function useLanguage(lang) {
  language = lang;
  bundle = new FluentBundle(lang, { useIsolating: false });
  loading.clear();
  rest = false;
  document.documentElement.lang = lang;
  await fetchPart('page');
  if (lang !== 'en') translatePage([...document.querySelectorAll('[data-l10n-id]')]);
}

/** The elements whose words come with the rest of the messages, until they come. */
let waiting = /** @type {Element[]} */ ([]);

/**
 * Writes the page's own words of `elements` in the language shown. The build wrote the English ones
 * into it (scripts/bundle.mjs): each element with a `data-l10n-id` holds its message's text, when
 * the message has one, and has its message's attributes; another language writes its own the same
 * way. An element inside `data-l10n-rest` whose message is of the rest waits for it.
 * @param {Element[]} elements
 */
function translatePage(elements) {
  waiting = [];
  for (const element of elements) {
    const id = /** @type {string} */ (element.getAttribute('data-l10n-id'));
    const message = bundle.getMessage(id);
    if (!message) {
      // The Analysis, Lessons and Challenge tabs' own words come with the rest of the messages.
      if (!rest && element.closest('[data-l10n-rest]')) waiting.push(element);
      else console.error(`no message ${id} in ${language}`);
      continue;
    }
    if (message.value !== null) element.textContent = t(id);
    for (const name of Object.keys(message.attributes)) element.setAttribute(name, t(`${id}.${name}`));
  }
}

/**
 * Fetches `part` of the language shown into its messages (those of the language shown when it was
 * asked for, should another be chosen meanwhile).
 * @param {'page' | 'rest'} part
 */
async function fetchPart(part) {
  const [lang, target] = [language, bundle];
  const url = FILES[lang]?.[part];
  if (!url) throw new Error(`no ${part} messages for ${lang}`);
  const response = await fetch(new URL(url, document.baseURI));
  if (!response.ok) throw new Error(`the ${lang} ${part} messages could not be loaded (${response.status})`);
  add(target, await response.text(), `${lang}/${part}`);
}

/**
 * Loads the rest of the messages of the language shown (the tools', the law editor's, the
 * challenges', the lessons' and the walkthrough's), once; a failed load is tried again when next
 * asked for.
 * @returns {Promise<void>}
 */
export function loadRest() {
  let promise = loading.get('rest');
  if (!promise) {
    promise = fetchPart('rest').then(
      () => {
        rest = true;
        if (waiting.length) translatePage(waiting);
      },
      (e) => {
        loading.delete('rest');
        throw e;
      },
    );
    loading.set('rest', promise);
  }
  return promise;
}

/**
 * Loads the rest of the messages, if not yet; resolves with null once they are, or with why they
 * could not be (page-messages-failed, a page message), for the part of the page that needed them.
 * @returns {Promise<string | null>}
 */
export const restReady = () =>
  loadRest().then(
    () => null,
    (e) => t('page-messages-failed', { reason: e.message }),
  );

let rest = false;
/** Whether the rest of the messages is loaded. */
export const restLoaded = () => rest;

/**
 * The message files the service worker keeps for offline use: the language shown's, and the
 * English page messages the page falls back to.
 */
export const languageFiles = () => [...new Set([...Object.values(FILES[language] ?? {}), FILES.en.page])];

/**
 * The message `id` (or its attribute, `id.attr`) with `args`, in the language shown. A message the
 * language lacks is a mistake of the page: logged, and the id shown.
 * @param {string} id
 * @param {Record<string, string | number | import('@fluent/bundle').FluentNumber>} [args]
 */
export function t(id, args) {
  const [name, attr] = id.split('.');
  const message = bundle.getMessage(name);
  const pattern = attr ? message?.attributes[attr] : message?.value;
  if (!pattern) {
    console.error(`no message ${id} in ${language}`);
    return id;
  }
  /** @type {Error[]} */
  const errors = [];
  const text = bundle.formatPattern(pattern, args, errors);
  if (errors.length) console.error(`message ${id} in ${language}: ${errors.join('; ')}`);
  return text;
}

/**
 * `value` shown in the language shown: its decimal separator and grouping (from five digits on),
 * a minus sign for negatives; `fraction` fixes the digits after the separator.
 * @param {number} value
 * @param {number} [fraction]
 */
export function num(value, fraction) {
  return new Intl.NumberFormat(language, {
    useGrouping: 'min2',
    ...(fraction === undefined ? {} : { minimumFractionDigits: fraction, maximumFractionDigits: fraction }),
  })
    .format(value)
    .replace(/^-/, '−');
}

/** @import { CoreMessage, Spoken } from './core-message.js' */

/**
 * What the worker said, in the language shown: a message of the core rendered from the language's
 * messages, or a text as it is (the page's own words, already in the language, or the core's not yet
 * given as a message).
 * @param {string | CoreMessage} text
 * @returns {string}
 */
function said(text) {
  if (!isCoreMessage(text)) return String(text);
  /** @type {Record<string, string | FluentNumber>} */
  const args = {};
  for (const [name, arg] of Object.entries(text.args)) {
    if (typeof arg === 'string') args[name] = arg;
    // A count as the core writes it, ungrouped: it may be a bound the reader types (B ≤ 9007199254740991).
    else if (typeof arg === 'number') args[name] = new FluentNumber(arg, { useGrouping: false });
    else if (Array.isArray(arg)) args[name] = arg.map(said).join(t('core-list-separator'));
    else if (isCoreMessage(arg)) args[name] = said(arg);
    else if ('real' in arg) args[name] = shortest(arg.real);
    else if ('sci' in arg) args[name] = scientific(arg.sci, arg.places);
    else args[name] = num(arg.fixed, arg.fraction);
  }
  return t(text.id, args);
}

/**
 * `value` with the fewest digits that read back to it, as the core writes it, with the language's
 * decimal separator.
 * @param {number} value
 */
function shortest(value) {
  const separator = new Intl.NumberFormat(language).formatToParts(0.5).find((p) => p.type === 'decimal')?.value ?? '.';
  return String(value).replace('.', separator);
}

/**
 * `value` in scientific notation with `places` decimals in its mantissa, in the language shown
 * (1,58e-4 in German), with a lower-case e as the core writes it in English.
 * @param {number} value
 * @param {number} places
 */
function scientific(value, places) {
  const format = { notation: 'scientific', minimumFractionDigits: places, maximumFractionDigits: places };
  return new Intl.NumberFormat(language, /** @type {Intl.NumberFormatOptions} */ (format))
    .format(value)
    .replace('E', 'e');
}

/**
 * `data` from the worker with every message of the core in it said in the language shown, in
 * place (typed arrays and other objects that are not plain are left as they are).
 * @template T
 * @param {T} data
 * @returns {Spoken<T>}
 */
export function spoken(data) {
  if (isCoreMessage(data)) return /** @type {Spoken<T>} */ (said(data));
  if (Array.isArray(data)) data.forEach((v, i) => (data[i] = spoken(v)));
  else if (typeof data === 'object' && data !== null && Object.getPrototypeOf(data) === Object.prototype)
    for (const [k, v] of Object.entries(data)) /** @type {Record<string, unknown>} */ (data)[k] = spoken(v);
  return /** @type {Spoken<T>} */ (data);
}
