// Service worker: network first, so a served update is always picked up; the cache answers when
// the network is gone, so a loaded app keeps working (and reloads) offline. Each file is cached
// once, under its path without the query: a scenario link's query changes the run, not the file,
// so a class opening hundreds of links keeps one copy of the page.
const CACHE = 'imlab-v1';

self.addEventListener('install', () => self.skipWaiting());
self.addEventListener('activate', (event) => event.waitUntil(self.clients.claim()));

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
