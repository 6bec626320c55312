// Calls that stay calls in the wasm, so that V8 can move their code to its
// optimising tier. V8 enters a wasm function in its baseline tier, compiles the
// function again optimised in the background once it is hot, and switches to
// the optimised code on the function's next call: a long loop in a function
// called once (a phase of a one-shot run) stays in baseline code to its end.
// Cutting such a loop into chunks, each chunk one call of a function of its
// own, lets the optimised code take over after the first chunks. The call goes
// through a function pointer the optimisers cannot see through: Binaryen
// inlines any function called from one place (`noinline` does not stop it),
// and the compiler would inline a direct call of the body. Only a wasm build
// takes the detour: a native build has no tiers, and there the opaque call
// would cost optimisations (the body's captured state escapes, so a byte store
// may alias it and it is reloaded per item), so natively the call is direct.
#pragma once
#include <algorithm>
#include <cstddef>
#include <utility>

namespace hodt {

// f(args...), called through a pointer read from a volatile, so that the body
// of f is a function of its own that no optimiser inlines into the caller. An
// lvalue argument is passed by reference, a temporary by value (as a direct
// call would pass a line's number and text).
template <class F, class... A>
decltype(auto) out_of_line(F& f, A&&... args) {
#if defined(__wasm__)
  using R = decltype(f(std::forward<A>(args)...));
  R (*volatile const call)(F&, A...) = [](F& g, A... a) -> R { return g(std::forward<A>(a)...); };
  return call(f, std::forward<A>(args)...);
#else
  return f(std::forward<A>(args)...);
#endif
}

// The items of a long loop per chunk: body(begin, end) for consecutive ranges
// that cover [0, n) in order, each call out of line.
inline constexpr size_t kOutOfLineChunk = 1024;
template <class F>
void for_each_chunk(size_t n, F&& body) {
  for (size_t begin = 0; begin < n; begin += kOutOfLineChunk)
    out_of_line(body, begin, std::min(n, begin + kOutOfLineChunk));
}

// for (I i = 0; i < n; ++i) body(i), per chunk as above.
template <class I, class F>
void for_each_index(I n, F&& body) {
  for_each_chunk(static_cast<size_t>(n), [&](size_t begin, size_t end) {
    for (I i = static_cast<I>(begin); i < static_cast<I>(end); ++i) body(i);
  });
}

}  // namespace hodt
