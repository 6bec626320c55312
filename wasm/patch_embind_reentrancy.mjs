// Makes Emscripten 3.1.6's embind invokers re-entrant. Built without dynamic
// execution (-sDYNAMIC_EXECUTION=0, so that the module runs under a Content
// Security Policy without 'unsafe-eval'), embind makes one invoker per bound
// function whose argument and destructor arrays are shared by every call of it.
// A call nested in another call of the same function (a solve of one terrain
// from the progress callback of another's solve) overwrites the outer call's
// arrays, and the outer call then frees the inner call's arguments a second
// time: a double free that corrupts the heap. The fix gives each call its own
// arrays, as later Emscripten versions do.
//
//   node wasm/patch_embind_reentrancy.mjs build/wasm/hodt.mjs
import { readFileSync, writeFileSync } from 'node:fs';

const file = process.argv[2];
const shared =
  'var expectedArgCount=argCount-2;var argsWired=new Array(expectedArgCount);var invokerFuncArgs=[];var destructors=[];return function(){';
const perCall =
  'var expectedArgCount=argCount-2;return function(){var argsWired=new Array(expectedArgCount);var invokerFuncArgs=[];var destructors=[];';
const glue = readFileSync(file, 'utf8');
const found = glue.split(shared).length - 1;
if (found > 1) throw new Error(`${file}: ${found} shared embind invokers, expected one`);
if (found === 1) writeFileSync(file, glue.replace(shared, perCall));
else if (!glue.includes(perCall) && /var destructors=\[\];return function\(\)\{/.test(glue))
  throw new Error(`${file}: embind's invoker shares its arrays in a form this patch does not know`);
