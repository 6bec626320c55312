// std::vector crosses into JS as a copy, never as a view of the wasm heap: a
// vector of numbers becomes the matching typed array, a vector of registered
// structs a plain array of their value objects. With this, the core's structs are
// registered field by field (value_object) and need no hand-built conversion.
#pragma once
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cstdint>
#include <type_traits>
#include <vector>

namespace hodt_wasm {

template <class T> constexpr const char* typed_array_name() {
  if constexpr (std::is_same_v<T, uint8_t>) return "Uint8Array";
  else if constexpr (std::is_same_v<T, int32_t>) return "Int32Array";
  else if constexpr (std::is_same_v<T, uint32_t>) return "Uint32Array";
  else if constexpr (std::is_same_v<T, double>) return "Float64Array";
  else return nullptr;
}

template <class T> emscripten::val to_js(const std::vector<T>& v) {
  if constexpr (typed_array_name<T>() != nullptr) {
    return emscripten::val::global(typed_array_name<T>()).new_(emscripten::typed_memory_view(v.size(), v.data()));
  } else {
    static_assert(std::is_class_v<T>, "a vector of numbers needs its typed array in typed_array_name");
    emscripten::val out = emscripten::val::array();
    for (const T& x : v) out.call<void>("push", emscripten::val(x));
    return out;
  }
}

}  // namespace hodt_wasm

namespace emscripten::internal {

template <class T> struct TypeID<std::vector<T>> {
  static constexpr TYPEID get() { return TypeID<val>::get(); }
};

template <class T> struct BindingType<std::vector<T>> {
  using WireType = BindingType<val>::WireType;
  static WireType toWireType(const std::vector<T>& v) { return BindingType<val>::toWireType(hodt_wasm::to_js(v)); }
  static std::vector<T> fromWireType(WireType w) { return vecFromJSArray<T>(BindingType<val>::fromWireType(w)); }
};

}  // namespace emscripten::internal
