// The router tests' drawing (mm), shared by tests/wasm/milling.test.mjs and tests/browser/milling.test.mjs
// (the Rust tests' twin: tests/common/mod.rs pocket_island_dxf): a 60 × 40 pocket around a round island of
// R 8 on layer POCKET, and a 30 × 30 square on PROFILE. Returns the DXF's text.
export function pocketIslandDxf() {
  const out = ['0', 'SECTION', '2', 'HEADER', '9', '$INSUNITS', '70', '4', '0', 'ENDSEC', '0', 'SECTION', '2', 'ENTITIES'];
  const poly = (layer, pts) => {
    out.push('0', 'LWPOLYLINE', '8', layer, '90', pts.length, '70', 1);
    for (const [x, y] of pts) out.push('10', x, '20', y);
  };
  poly('POCKET', [[0, 0], [60, 0], [60, 40], [0, 40]]);
  out.push('0', 'CIRCLE', '8', 'POCKET', '10', 30, '20', 20, '40', 8);
  poly('PROFILE', [[80, 0], [110, 0], [110, 30], [80, 30]]);
  out.push('0', 'ENDSEC', '0', 'EOF');
  return out.map(String).join('\n') + '\n';
}
