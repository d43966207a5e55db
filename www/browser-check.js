// kerfcam page: what the browser must have before the engine loads. The cutting core is built with
// WebAssembly SIMD (issue 17, .cargo/config.toml): a browser without it would fail to compile the
// engine with a message that names an opcode. Asked first, the page says instead which browsers run it.

import { register } from './i18n.js';

register({
  en: {
    'error.no-simd':
      'This browser is too old for kerfcam\'s cutting engine: it needs WebAssembly SIMD. ' +
      'Use Chrome or Edge 91 or later, Firefox 89 or later, or Safari 16.4 or later (all free, and they work offline).',
  },
  'pt-BR': {
    'error.no-simd':
      'Este navegador é antigo demais para o motor de corte do kerfcam: ele precisa de WebAssembly SIMD. ' +
      'Use Chrome ou Edge 91 ou mais novo, Firefox 89 ou mais novo, ou Safari 16.4 ou mais novo (todos gratuitos, e funcionam sem internet).',
  },
});

// The smallest module that needs SIMD: one function () -> v128 whose body is `i32.const 0; i8x16.splat`.
const SIMD_PROBE = new Uint8Array([
  0, 97, 115, 109, 1, 0, 0, 0, // "\0asm", version 1
  1, 5, 1, 96, 0, 1, 123, // type section: () -> v128
  3, 2, 1, 0, // function section: one function of type 0
  10, 8, 1, 6, 0, 65, 0, 253, 15, 11, // code: no locals, i32.const 0, i8x16.splat, end
]);

/** True when this browser runs WebAssembly with SIMD, as the engine is built. */
export function engineSupported() {
  try {
    return typeof WebAssembly === 'object' && WebAssembly.validate(SIMD_PROBE);
  } catch {
    return false;
  }
}
