// The page's message files. The build (scripts/bundle.mjs) writes here the English page messages'
// text, which the page needs before its first plot and so carries in its bundle, and the address
// of every other file: each language's page messages (`page`) and the rest (`rest`).
/** @type {string} */
export const EN_PAGE = '';
/** @type {Record<string, {page?: string, rest: string}>} */
export const FILES = {};
