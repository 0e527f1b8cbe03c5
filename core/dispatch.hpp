// From a runtime index into a std::tuple of types to compiled code: calls
// f.template operator()<T>() with T the index-th type. A jump table, so void results work too.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace steplab {

template <class Tuple, class F> decltype(auto) visit_type(std::size_t index, F&& f) {
  using R = decltype(f.template operator()<std::tuple_element_t<0, Tuple>>());
  return [&]<std::size_t... I>(std::index_sequence<I...>) -> R {
    using Fn = R (*)(F&);
    static constexpr Fn table[] = {
        +[](F& g) -> R { return g.template operator()<std::tuple_element_t<I, Tuple>>(); }...};
    if (index >= sizeof...(I)) throw std::out_of_range("type index out of range");
    return table[index](f);
  }(std::make_index_sequence<std::tuple_size_v<Tuple>>{});
}

}  // namespace steplab
