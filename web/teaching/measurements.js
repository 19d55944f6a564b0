// The lessons' tables of measurements (web/teaching/measurements/*.csv, as `imlab claims` writes
// them), one string each: the build puts their texts here (scripts/bundle.mjs), so the page
// carries the table its lessons were checked against.
/** @type {string[]} */
export const TABLES = [];
