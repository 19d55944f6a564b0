// The page's message files. The build (scripts/bundle.mjs) writes here the address of each
// language's page messages (`page`, fetched as the page starts) and of the rest (`rest`).
/** @type {Record<string, {page: string, rest: string}>} */
export const FILES = {};
