// A generated nest for the big-file test (issue 6 §2): rows of parts, each a rounded rectangle
// (LWPOLYLINE with bulge-arc corners) with two round holes (CIRCLE) and a rounded slot (LWPOLYLINE),
// repeated until the file reaches the size asked for. Written in pieces, never held whole in memory.
//
//   node tests/browser/big-dxf.mjs OUT.dxf [MEGABYTES]   (default 25)

import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const BULGE_90 = Math.tan(Math.PI / 8); // a quarter circle
const num = (x) => x.toFixed(6); // as many decimals as CAD exports usually write

/** Closed LWPOLYLINE: a w×h rectangle at (x, y) with corners rounded by r, counter-clockwise. */
function roundedRect(layer, x, y, w, h, r) {
  const v = [
    [x + r, y, 0], [x + w - r, y, BULGE_90], [x + w, y + r, 0], [x + w, y + h - r, BULGE_90],
    [x + w - r, y + h, 0], [x + r, y + h, BULGE_90], [x, y + h - r, 0], [x, y + r, BULGE_90],
  ];
  let s = `  0\nLWPOLYLINE\n  8\n${layer}\n 90\n${v.length}\n 70\n1\n`;
  for (const [px, py, b] of v) s += ` 10\n${num(px)}\n 20\n${num(py)}\n${b ? ` 42\n${num(b)}\n` : ''}`;
  return s;
}

const circle = (layer, cx, cy, r) => `  0\nCIRCLE\n  8\n${layer}\n 10\n${num(cx)}\n 20\n${num(cy)}\n 30\n0.0\n 40\n${num(r)}\n`;

/** One part: 60×36 mm outer, corner radius 5, two Ø8 holes and a 20×8 slot. */
function part(x, y) {
  return (
    roundedRect('PARTS', x, y, 60, 36, 5) +
    circle('PARTS', x + 12, y + 18, 4) +
    circle('PARTS', x + 48, y + 18, 4) +
    roundedRect('PARTS', x + 20, y + 14, 20, 8, 3)
  );
}

/** Writes the nest to `file` until it is at least `bytes` long; returns { bytes, parts, contours }. */
export function writeBigDxf(file, bytes = 25 * 1024 * 1024) {
  const head = '  0\nSECTION\n  2\nHEADER\n  9\n$ACADVER\n  1\nAC1015\n  9\n$INSUNITS\n 70\n4\n  0\nENDSEC\n' +
    '  0\nSECTION\n  2\nENTITIES\n';
  const tail = '  0\nENDSEC\n  0\nEOF\n';
  const perPart = Buffer.byteLength(part(1000.5, 1000.5));
  const parts = Math.ceil((bytes - head.length - tail.length) / perPart);
  const columns = Math.ceil(Math.sqrt(parts * 0.6)); // a roughly square sheet
  const fd = fs.openSync(file, 'w');
  try {
    fs.writeSync(fd, head);
    let chunk = '';
    for (let i = 0; i < parts; i++) {
      chunk += part((i % columns) * 66, Math.floor(i / columns) * 42);
      if (chunk.length > 1 << 20) {
        fs.writeSync(fd, chunk);
        chunk = '';
      }
    }
    fs.writeSync(fd, chunk + tail);
  } finally {
    fs.closeSync(fd);
  }
  return { bytes: fs.statSync(file).size, parts, contours: parts * 4 };
}

const isMain = process.argv[1] && path.resolve(process.argv[1]) === fileURLToPath(import.meta.url);
if (isMain) {
  const r = writeBigDxf(process.argv[2], Number(process.argv[3] ?? 25) * 1024 * 1024);
  console.log(`${process.argv[2]}: ${r.bytes} bytes, ${r.parts} parts, ${r.contours} contours`);
}
