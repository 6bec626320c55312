// memset, memcpy and memmove as WebAssembly's bulk memory instructions.
//
// This Emscripten's C library fills memory with a loop of word stores and copies
// blocks of 512 bytes or more through a call out to JavaScript. A long fill (the
// zeroed buffer a file is read into, a vector of millions of zeros) is one call,
// so it runs to its end in V8's baseline code. memory.fill and memory.copy are
// single instructions the engine carries out with the host's own memset and
// memmove, in either tier. memory.copy allows overlap, so it is memmove too.
//
// Only this file is compiled with -mbulk-memory (CMakeLists.txt): enabling it
// for the whole build makes this Emscripten's linker demand the atomics feature
// for thread-local storage. Every engine hodt.wasm runs on (it needs wasm
// exceptions) has bulk memory.
#include <cstddef>

extern "C" {

void* memset(void* dest, int c, std::size_t n) { return __builtin_memset(dest, c, n); }

void* memcpy(void* __restrict dest, const void* __restrict src, std::size_t n) {
  return __builtin_memcpy(dest, src, n);
}

void* memmove(void* dest, const void* src, std::size_t n) { return __builtin_memmove(dest, src, n); }

}  // extern "C"
