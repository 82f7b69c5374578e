#pragma once
// The number of members of an aggregate, found by brace-initialising it from ever more values
// of a type that converts to anything. Boost.PFR does this, but Debian 12's Boost 1.74 predates
// it (no boost/pfr.hpp). Members that are arrays or take no copy from a conversion (references,
// non-movable types) would miscount; the settings structs hold numbers, enums and structs.
#include <cstddef>
#include <type_traits>
#include <utility>

namespace slamkit {
namespace aggregate_arity_detail {

// Converts to any member type; only named in unevaluated contexts, hence never defined.
template <size_t>
struct AnyMember {
  template <class T>
  operator T() const;
};

template <class T, class Indices, class = void>
struct BraceInitializable : std::false_type {};
template <class T, size_t... I>
struct BraceInitializable<T, std::index_sequence<I...>, std::void_t<decltype(T{AnyMember<I>{}...})>>
    : std::true_type {};

template <class T, size_t N>
constexpr size_t count_from() {
  if constexpr (BraceInitializable<T, std::make_index_sequence<N + 1>>::value)
    return count_from<T, N + 1>();
  else
    return N;
}

}  // namespace aggregate_arity_detail

template <class T>
constexpr size_t aggregate_arity() {
  static_assert(std::is_aggregate_v<T>, "only an aggregate's members can be counted");
  return aggregate_arity_detail::count_from<T, 0>();
}

}  // namespace slamkit
