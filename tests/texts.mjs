// The page's texts as the tests read them: each language's messages (web/locales/LANG/*.ftl), and
// the lessons with their texts as templates whose placeholders name measurements.
import { readFileSync } from 'node:fs';
import { LESSONS } from '../web/teaching/teaching.js';
import { LESSON_TEXTS, placeholdersOf } from '../web/teaching/measured.js';
import { messages } from '../scripts/l10n-lint.mjs';

const LOCALES = new URL('../web/locales/', import.meta.url).pathname;

/**
 * The messages of `lang`'s `file` (e.g. 'lessons.ftl'), by id, as written.
 * @param {string} lang
 * @param {string} file
 */
export const messagesOf = (lang, file) => messages(readFileSync(`${LOCALES}${lang}/${file}`, 'utf8'));

/**
 * The lessons with their texts in `lang`, each a template ({id} for a measurement).
 * @param {string} [lang]
 */
export function lessonsIn(lang = 'en') {
  const texts = messagesOf(lang, 'lessons.ftl');
  return LESSONS.map((lesson) => {
    const own = LESSON_TEXTS.map((k) => {
      const text = texts.get(`${lesson.id}-${k}`);
      if (text === undefined) throw new Error(`${lang}/lessons.ftl has no ${lesson.id}-${k}`);
      return [k, placeholdersOf(text)];
    });
    return { ...lesson, ...Object.fromEntries(own) };
  });
}
