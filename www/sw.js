// kerfcam service worker: the app works with the network gone. Network first (a rebuilt app is
// picked up at once when the server is there), the cached copy when it is not. Only this app's own
// files are cached; kerfcam asks no other host for anything, ever.

const CACHE = 'kerfcam-v25';
const SHELL = [
  './', './index.html', './style.css', './main.js', './browser-check.js', './plan.js', './posts.js', './engine.js', './worker.js',
  './settings-store.js', './download.js', './i18n.js', './page-strings.js', './progress.js', './batch.js',
  './file-store.js', './inspect.js', './jobsheet.js', './numbers.js', './origin.js', './summary.js', './units.js',
  './layout.js', './app.js', './job.js', './view.js', './layers.js', './backplot.js', './sheet.js', './nest-run.js', './nest-team.js', './nest-view.js', './nest-edit.js', './nest-file.js', './nest-tabs.js', './nest-store.js', './part-row.js', './sheet-sizes.js',
  './vendor/fflate.js', './pkg/kerfcam.js', './pkg/kerfcam_bg.wasm',
  './pkg/kerfcam_nest.js', './pkg/kerfcam_nest_bg.wasm',
  './process.js', './materials.js', './tabs-tool.js', './side-tool.js', './choices.js', './losses.js', './cost.js', './labels.js', './job-report.js', './tool.js',
];

self.addEventListener('install', (e) => {
  e.waitUntil(caches.open(CACHE).then((c) => c.addAll(SHELL)).then(() => self.skipWaiting()));
});

self.addEventListener('activate', (e) => {
  e.waitUntil(
    caches.keys()
      .then((keys) => Promise.all(keys.filter((k) => k !== CACHE).map((k) => caches.delete(k))))
      .then(() => self.clients.claim()),
  );
});

self.addEventListener('fetch', (e) => {
  const url = new URL(e.request.url);
  if (e.request.method !== 'GET' || url.origin !== self.location.origin) return;
  e.respondWith(
    fetch(e.request)
      .then((response) => {
        if (response.ok) {
          const copy = response.clone();
          e.waitUntil(caches.open(CACHE).then((c) => c.put(e.request, copy)));
        }
        return response;
      })
      .catch(async () => (await caches.match(e.request, { ignoreSearch: true })) ??
        new Response('offline and not cached', { status: 503, headers: { 'Content-Type': 'text/plain' } })),
  );
});
