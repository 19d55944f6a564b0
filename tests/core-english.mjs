// The core's messages in English, as the CLI says them (from web/locales/en/core-*.ftl), for the
// tests that read a message the core gives the page: counts with no grouping, as Rust writes
// them, and every other argument as the page's `said()` renders it in English.
import { readFileSync, readdirSync } from 'node:fs';
import { FluentBundle, FluentNumber, FluentResource } from '@fluent/bundle';

const EN = new URL('../web/locales/en/', import.meta.url).pathname;
const bundle = new FluentBundle('en', { useIsolating: false });
for (const file of readdirSync(EN).filter((f) => /^core-.+\.ftl$/.test(f))) {
  const errors = bundle.addResource(new FluentResource(readFileSync(EN + file, 'utf8')));
  if (errors.length) throw new Error(`${file}: ${errors.join('; ')}`);
}

/**
 * `message` (the core's `{id, args}`, or a text, returned as it is) in English.
 * @param {string | {id: string, args: Record<string, unknown>}} message
 * @returns {string}
 */
export function english(message) {
  if (typeof message === 'string') return message;
  const found = bundle.getMessage(message.id);
  if (!found?.value) throw new Error(`no English message ${message.id}`);
  const args = {};
  for (const [name, arg] of Object.entries(message.args)) {
    if (typeof arg === 'string') args[name] = arg;
    else if (typeof arg === 'number') args[name] = new FluentNumber(arg, { useGrouping: false });
    else if (Array.isArray(arg)) args[name] = arg.map(english).join(', ');
    else if ('id' in arg) args[name] = english(arg);
    else if ('real' in arg) args[name] = String(arg.real);
    else args[name] = arg.fixed.toFixed(arg.fraction);
  }
  const errors = [];
  const text = bundle.formatPattern(found.value, args, errors);
  if (errors.length) throw new Error(`message ${message.id}: ${errors.join('; ')}`);
  return text;
}
