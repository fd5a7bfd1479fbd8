// A word a shape policy may keep per neighbour-list entry between steps (a polyhedron pair's
// last separating axis): shapes that do say so with kKeepsPairHints = true. The broad phase then
// holds one 16-bit word per entry and sets it to kNoPairHint at every list build; the contact
// kernel hands the entry's word to collide(). It is a cache: it never changes a contact.
#pragma once
#include <cstdint>
#include <type_traits>

namespace blaze {

inline constexpr std::uint16_t kNoPairHint = 0xFFFF;

template <class Shape, class = void>
struct KeepsPairHints : std::false_type {};
template <class Shape>
struct KeepsPairHints<Shape, std::void_t<decltype(Shape::kKeepsPairHints)>> : std::bool_constant<Shape::kKeepsPairHints> {};
template <class Shape>
inline constexpr bool keeps_pair_hints_v = KeepsPairHints<Shape>::value;

}  // namespace blaze
