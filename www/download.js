// kerfcam page: hands a Blob to the browser as a file download (G-code, pictures, posts).

/** Downloads `blob` as `name`. */
export function download(blob, name) {
  const a = Object.assign(document.createElement('a'), { href: URL.createObjectURL(blob), download: name });
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 10_000);
}
