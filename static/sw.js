// Service worker: network first, so a served update is always picked up; the cache answers when
// the network is gone, so a loaded app keeps working (and reloads) offline. Each file is cached
// once, under its path without the query: a scenario link's query changes the run, not the file,
// so a class opening hundreds of links keeps one copy of the page.
const CACHE = 'imlab-v1';

// What the page fetches only later, if at all (the core built with its tools and the jobs, KaTeX,
// its stylesheet and fonts, the walkthrough's diagram), with every other file named by its hash: fetched when the service
// worker installs, so that a loaded app has them offline too. The build (scripts/bundle.mjs)
// writes the list into the copy of this file it serves.
const PRECACHE = [];

// A file named by its content's hash (main-JRYEWMOB.js): one of an older build once not listed.
const HASHED = /-[A-Z2-7]{8}\.[a-z0-9]+$/;

self.addEventListener('install', (event) => {
  self.skipWaiting();
  event.waitUntil(caches.open(CACHE).then((cache) => cache.addAll(PRECACHE)));
});

// Once active: controls the open pages, and drops the hashed files of older builds.
self.addEventListener('activate', (event) =>
  event.waitUntil(
    (async () => {
      await self.clients.claim();
      const listed = new Set(PRECACHE.map((path) => new URL(path, self.location.href).href));
      const cache = await caches.open(CACHE);
      for (const request of await cache.keys())
        if (HASHED.test(new URL(request.url).pathname) && !listed.has(request.url)) await cache.delete(request);
    })(),
  ),
);

// The page names the files of the language it shows (`{keep: [path, …]}`), once this worker is
// active: they are kept for offline use, and no other language's are fetched. The port sent with
// the message hears whether they were kept.
self.addEventListener('message', (event) => {
  const keep = event.data?.keep;
  if (!Array.isArray(keep) || !keep.every((path) => typeof path === 'string' && path.startsWith('locales/'))) return;
  const kept = caches
    .open(CACHE)
    .then((cache) => cache.addAll(keep))
    .then(
      () => true,
      () => false,
    );
  event.waitUntil(kept.then((ok) => event.ports[0]?.postMessage({ kept: ok })));
});

self.addEventListener('fetch', (event) => {
  if (event.request.method !== 'GET' || !event.request.url.startsWith(self.location.origin)) return;
  event.respondWith(
    fetch(event.request)
      .then((response) => {
        if (response.ok) {
          const copy = response.clone();
          const key = new URL(event.request.url);
          key.search = '';
          caches.open(CACHE).then((cache) => cache.put(key.href, copy));
        }
        return response;
      })
      .catch(() => caches.match(event.request, { ignoreSearch: true }).then((hit) => hit ?? Response.error())),
  );
});
