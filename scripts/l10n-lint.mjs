// Checks the translations in web/locales/LANG/*.ftl against the English files in
// web/locales/en/: every English message is translated, with the same variables, no message the
// English lacks, no number the English message does not state, and the language's glossary
// (web/locales/LANG/glossary.tsv) followed. tests/l10n.test.mjs runs the same checks.
//
//   node scripts/l10n-lint.mjs [LANG...]
import { readFileSync, readdirSync, existsSync } from 'node:fs';
import { FluentResource } from '@fluent/bundle';
import { LANGUAGES } from '../web/l10n/languages.js';

const ROOT = new URL('../web/locales/', import.meta.url).pathname;
/** The translations: every language the page speaks but English. */
export const LANGS = LANGUAGES.map(([code]) => code).filter((code) => code !== 'en');

/**
 * The messages of an FTL text: id (or id.attribute) → its source text, with the parser's errors.
 * @param {string} text
 */
export function messages(text) {
  const resource = new FluentResource(text);
  /** @type {Map<string, string>} */
  const out = new Map();
  const source = (pattern) =>
    typeof pattern === 'string'
      ? pattern
      : pattern
          .map((p) =>
            typeof p === 'string'
              ? p
              : p.type === 'var'
                ? `{$${p.name}}`
                : p.type === 'select'
                  ? p.variants.map((v) => source(v.value)).join(' ')
                  : p.type === 'str'
                    ? p.value
                    : `{${p.type}}`,
          )
          .join('');
  for (const m of resource.body) {
    if (m.value !== null) out.set(m.id, source(m.value));
    for (const [name, pattern] of Object.entries(m.attributes)) out.set(`${m.id}.${name}`, source(pattern));
  }
  return out;
}

const VARIABLE = /\{\$([A-Za-z0-9_-]+)\}/g;
export const variablesOf = (text) => [...new Set([...text.matchAll(VARIABLE)].map((m) => m[1]))].sort();
export const numbersOf = (text) => [...text.replace(VARIABLE, ' ').matchAll(/\d+/g)].map((m) => m[0]);

/**
 * The glossary of `lang` (a header line, then one term a line, tab-separated): the English term,
 * its translation as the language's control textbooks write it, the part of it every inflected
 * form holds (the translation itself when empty), and other words for it the texts must not use
 * (comma-separated).
 */
export function glossary(lang) {
  const path = `${ROOT}${lang}/glossary.tsv`;
  if (!existsSync(path)) return [];
  return readFileSync(path, 'utf8')
    .split('\n')
    .slice(1)
    .filter((l) => l.trim() && !l.startsWith('#'))
    .map((l) => {
      const [en, term, match = '', avoid = ''] = l.split('\t');
      return {
        en,
        term: match || term,
        avoid: avoid
          .split(',')
          .map((a) => a.trim())
          .filter(Boolean),
      };
    });
}

/**
 * The words of a message's text: without its variables, its code, its settings (`k1=600`,
 * `model.j`) and the field names it quotes ('preset').
 * @param {string} text
 */
const prose = (text) =>
  text
    .replace(VARIABLE, ' ')
    .replace(/`[^`]*`/g, ' ')
    .replace(/'[\w.]+'/g, ' ')
    .replace(/[\w.-]*[=.:][\w.-]*[a-z0-9]/gi, ' ');

/**
 * A pattern that finds `word` where a word starts (so "rating" is not found in "integrating").
 * @param {string} word
 */
const startsWord = (word) => new RegExp(`(^|[^\\p{L}])${word.replace(/[.*+?^${}()|[\]\\]/g, '\\$&')}`, 'iu');

/**
 * The problems of `lang`'s translation of the English file `file` (e.g. 'lessons.ftl'); `given`
 * replaces the files and the glossary (for the checks' own test).
 * @param {string} lang
 * @param {string} file
 * @param {{en: string, tr: string, glossary: ReturnType<typeof glossary>}} [given]
 */
export function problems(lang, file, given) {
  const path = `${ROOT}${lang}/${file}`;
  if (!given && !existsSync(path)) return [`${lang}/${file}: missing`];
  const en = messages(given?.en ?? readFileSync(`${ROOT}en/${file}`, 'utf8'));
  const tr = messages(given?.tr ?? readFileSync(path, 'utf8'));
  const out = [];
  for (const id of en.keys()) if (!tr.has(id)) out.push(`${lang}/${file}: ${id} is not translated`);
  for (const id of tr.keys()) if (!en.has(id)) out.push(`${lang}/${file}: ${id} is not an English message`);
  const terms = given?.glossary ?? glossary(lang);
  for (const [id, text] of tr) {
    const source = en.get(id);
    if (source === undefined) continue;
    const [a, b] = [variablesOf(source), variablesOf(text)];
    if (a.join() !== b.join())
      out.push(`${lang}/${file}: ${id} has variables ${b.join(' ')}, the English ${a.join(' ')}`);
    const left = numbersOf(source);
    for (const n of numbersOf(text)) {
      const at = left.indexOf(n);
      if (at < 0) out.push(`${lang}/${file}: ${id} states ${n}, which the English does not`);
      else left.splice(at, 1);
    }
    // A term is read in the words of the English, not in a variable's name, code or a setting.
    const words = prose(source);
    const translated = prose(text).toLowerCase();
    for (const { en: word, term, avoid } of terms) {
      if (!startsWord(word).test(words)) continue;
      if (!translated.includes(term.toLowerCase()))
        out.push(`${lang}/${file}: ${id} says “${word}” in English but not “${term}”`);
      for (const a of avoid)
        if (translated.includes(a.toLowerCase())) out.push(`${lang}/${file}: ${id} says “${a}”, not “${term}”`);
    }
  }
  return out;
}

/**
 * The labels of the page that `lang`'s lessons quote (web/locales/LANG/ui-terms.tsv: the English
 * label, the words the lessons use) that the page's own message for that label does not say.
 * @param {string} lang
 */
export function quotedLabels(lang) {
  const path = `${ROOT}${lang}/ui-terms.tsv`;
  if (!existsSync(path)) return [];
  const files = readdirSync(`${ROOT}en`).filter((f) => f.endsWith('.ftl') && existsSync(`${ROOT}${lang}/${f}`));
  const en = new Map(files.flatMap((f) => [...messages(readFileSync(`${ROOT}en/${f}`, 'utf8'))]));
  const tr = new Map(files.flatMap((f) => [...messages(readFileSync(`${ROOT}${lang}/${f}`, 'utf8'))]));
  const out = [];
  for (const line of readFileSync(path, 'utf8').split('\n').slice(1)) {
    const [label, words] = line.split('\t');
    if (!label || !words) continue;
    const ids = [...en].filter(([, text]) => text.trim() === label.trim()).map(([id]) => id);
    for (const id of ids)
      if (tr.has(id) && tr.get(id).trim() !== words.trim())
        out.push(`${lang}: the lessons quote “${label}” as “${words}”, the page (${id}) says “${tr.get(id)}”`);
  }
  return out;
}

if (process.argv[1] === new URL(import.meta.url).pathname) {
  const langs = process.argv.length > 2 ? process.argv.slice(2) : LANGS;
  const files = readdirSync(`${ROOT}en`).filter((f) => f.endsWith('.ftl'));
  const found = langs.flatMap((lang) => [...files.flatMap((f) => problems(lang, f)), ...quotedLabels(lang)]);
  for (const p of found) console.log(p);
  console.log(`${found.length} problems`);
  process.exit(found.length ? 1 : 0);
}
