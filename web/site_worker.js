// The static site's service worker (tools/site writes it as sw.js, with this build's files and
// their digest in place of the two names below): the lab opens offline once it has been opened.
// Every file of the build is cached when the worker installs; a request is answered from the
// cache first, from the network for anything else. A new build has a new digest, so a new worker,
// which caches the new files and deletes the old build's cache.
const VERSION = "frictionlab-" + SITE_DIGEST;
const FILES = SITE_FILES;

self.addEventListener("install", (event) => {
  event.waitUntil(
    caches
      .open(VERSION)
      .then((cache) => cache.addAll(FILES))
      .then(() => self.skipWaiting()),
  );
});

self.addEventListener("activate", (event) => {
  event.waitUntil(
    caches
      .keys()
      .then((names) =>
        Promise.all(
          names
            .filter((name) => name.startsWith("frictionlab-") && name !== VERSION)
            .map((name) => caches.delete(name)),
        ),
      )
      .then(() => self.clients.claim()),
  );
});

self.addEventListener("fetch", (event) => {
  if (event.request.method !== "GET") return;
  event.respondWith(
    caches
      .open(VERSION)
      // A link's set-up is in its query: the page is the same file whatever the link says.
      .then((cache) => cache.match(event.request, { ignoreSearch: true }))
      .then((hit) => hit ?? fetch(event.request)),
  );
});
