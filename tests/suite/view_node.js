// Runs the committed WebAssembly module of `collide view`'s page (wasm/collide_view.wasm) under
// Node, as the page does (src/view/assets/page.js): instantiate the bytes with no imports, write
// each request (UTF-8 JSON) into memory from `alloc`, `call` it, read the answer of the returned
// length at `answer()`. Reads a JSON array of requests on stdin; prints a JSON array of the
// answers' texts, exactly as the module wrote them. Usage: node view_node.js MODULE.wasm
'use strict';
const fs = require('node:fs');

async function main() {
  const bytes = fs.readFileSync(process.argv[2]);
  const { instance } = await WebAssembly.instantiate(bytes, {});
  const ex = instance.exports;
  const encoder = new TextEncoder();
  const decoder = new TextDecoder('utf-8', { fatal: true });
  const requests = JSON.parse(fs.readFileSync(0, 'utf8'));
  const answers = requests.map((request) => {
    const input = encoder.encode(JSON.stringify(request));
    const at = ex.alloc(input.length);
    new Uint8Array(ex.memory.buffer, at, input.length).set(input);
    const n = ex.call(at, input.length);
    return decoder.decode(new Uint8Array(ex.memory.buffer, ex.answer(), n));
  });
  process.stdout.write(JSON.stringify(answers));
}

main().catch((e) => {
  process.stderr.write(`${e.stack || e}\n`);
  process.exit(1);
});
