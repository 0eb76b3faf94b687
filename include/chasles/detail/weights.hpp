// chasles: the weights of the functions that reduce a range (mean.hpp,
// align.hpp) when the caller gives none.
#pragma once

namespace chasles {
namespace detail {

/// The weight 1 for every element: an iterator that never moves.
template <typename Scalar>
struct UnitWeights {
  Scalar one{1};
  const Scalar& operator*() const noexcept { return one; }
  UnitWeights& operator++() noexcept { return *this; }
};

}  // namespace detail
}  // namespace chasles
