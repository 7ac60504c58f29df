// Per-target part of kinetic/batch.cpp (included there once per SIMD target, hence Highway's
// toggling include guard instead of #pragma once): a pack of lanes as two Highway vectors of N
// lanes (16 lanes with AVX-512, 8 with AVX2, 4 with SSE4 or NEON), and the operations the kernel
// uses, lane by lane over both. Each operation is issued for the two vectors side by side:
// independent dependency chains that the CPU overlaps (the kernel's step is one long chain).
// Highway: https://github.com/google/highway (hwy/highway.h).
#if defined(COLDBLAST_KINETIC_BATCH_PACK_HPP_) == defined(HWY_TARGET_TOGGLE)
#ifdef COLDBLAST_KINETIC_BATCH_PACK_HPP_
#undef COLDBLAST_KINETIC_BATCH_PACK_HPP_
#else
#define COLDBLAST_KINETIC_BATCH_PACK_HPP_
#endif

#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>

#include <cstddef>
#include <cstdint>

#include "kinetic/batch.hpp"

// Not for one lane (the scalar loop is that) nor for targets without 64-bit lanes.
#if HWY_TARGET != HWY_SCALAR && HWY_TARGET != HWY_EMU128 && HWY_HAVE_FLOAT64 && HWY_HAVE_INTEGER64
HWY_BEFORE_NAMESPACE();
namespace coldblast::kinetic::HWY_NAMESPACE::pack {
namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::CappedTag<double, 8>;           // one vector of doubles
constexpr std::size_t N = hn::MaxLanes(DF());  // its lanes: 8, 4 or 2
constexpr std::size_t K = 2;                   // vectors per pack
constexpr std::size_t lanes = K * N;           // a pack's lanes: 16, 8 or 4
static_assert(batch_lanes % lanes == 0, "a pack's lanes divide the batch's");

/// A pack's lanes of T (double, int64 or uint64), lane l in vector l / N.
template <class T>
struct Pack {
  using D = hn::Rebind<T, DF>;
  hn::Vec<D> v[K];
};
/// A lane mask of a pack.
struct Mask {
  hn::Mask<DF> v[K];
};

/// r.v[k] = f(a.v[k], ...) for every vector k.
template <class R, class F, class... A>
HWY_INLINE R each(F f, const A&... a) {
  R r;
  for (std::size_t k = 0; k < K; ++k) r.v[k] = f(a.v[k]...);
  return r;
}

template <class T>
HWY_INLINE Pack<T> set(T x) {
  Pack<T> r;
  for (auto& v : r.v) v = hn::Set(typename Pack<T>::D(), x);
  return r;
}
/// The lanes of `lanes` values from p (aligned to 8 N bytes).
template <class T>
HWY_INLINE Pack<T> load(const T* p) {
  Pack<T> r;
  for (std::size_t k = 0; k < K; ++k) r.v[k] = hn::Load(typename Pack<T>::D(), p + k * N);
  return r;
}
template <class T>
HWY_INLINE void store(const Pack<T>& x, T* p) {
  for (std::size_t k = 0; k < K; ++k) hn::Store(x.v[k], typename Pack<T>::D(), p + k * N);
}
/// The lanes of m set to x, the others unchanged: AVX-512's masked store, elsewhere a load, a
/// blend and a store (AVX2's masked store is slower).
template <class T>
HWY_INLINE void store(const Pack<T>& x, const Mask& m, T* p) {
  const typename Pack<T>::D d;
  for (std::size_t k = 0; k < K; ++k) {
#if HWY_TARGET <= HWY_AVX3
    hn::BlendedStore(x.v[k], hn::RebindMask(d, m.v[k]), d, p + k * N);
#else
    hn::Store(hn::IfThenElse(hn::RebindMask(d, m.v[k]), x.v[k], hn::Load(d, p + k * N)), d, p + k * N);
#endif
  }
}

template <class T>
HWY_INLINE Pack<T> operator+(const Pack<T>& a, const Pack<T>& b) {
  return each<Pack<T>>([](auto x, auto y) HWY_ATTR { return hn::Add(x, y); }, a, b);
}
template <class T>
HWY_INLINE Pack<T> operator-(const Pack<T>& a, const Pack<T>& b) {
  return each<Pack<T>>([](auto x, auto y) HWY_ATTR { return hn::Sub(x, y); }, a, b);
}
template <class T>
HWY_INLINE Pack<T> operator*(const Pack<T>& a, const Pack<T>& b) {
  return each<Pack<T>>([](auto x, auto y) HWY_ATTR { return hn::Mul(x, y); }, a, b);
}
HWY_INLINE Pack<double> operator/(const Pack<double>& a, const Pack<double>& b) {
  return each<Pack<double>>([](auto x, auto y) HWY_ATTR { return hn::Div(x, y); }, a, b);
}
HWY_INLINE Pack<double> operator-(const Pack<double>& a) {
  return each<Pack<double>>([](auto x) HWY_ATTR { return hn::Neg(x); }, a);
}
HWY_INLINE Pack<std::uint64_t> operator^(const Pack<std::uint64_t>& a, const Pack<std::uint64_t>& b) {
  return each<Pack<std::uint64_t>>([](auto x, auto y) HWY_ATTR { return hn::Xor(x, y); }, a, b);
}
template <class T>
HWY_INLINE Pack<T> min(const Pack<T>& a, const Pack<T>& b) {
  return each<Pack<T>>([](auto x, auto y) HWY_ATTR { return hn::Min(x, y); }, a, b);
}
template <class T>
HWY_INLINE Pack<T> max(const Pack<T>& a, const Pack<T>& b) {
  return each<Pack<T>>([](auto x, auto y) HWY_ATTR { return hn::Max(x, y); }, a, b);
}
HWY_INLINE Pack<double> sqrt(const Pack<double>& a) {
  return each<Pack<double>>([](auto x) HWY_ATTR { return hn::Sqrt(x); }, a);
}
HWY_INLINE Pack<double> abs(const Pack<double>& a) {
  return each<Pack<double>>([](auto x) HWY_ATTR { return hn::Abs(x); }, a);
}
HWY_INLINE Pack<double> round(const Pack<double>& a) {
  return each<Pack<double>>([](auto x) HWY_ATTR { return hn::Round(x); }, a);
}
/// a b + c, fused where the target has FMA (AVX-512, AVX2, NEON; not SSE4).
HWY_INLINE Pack<double> mul_add(const Pack<double>& a, const Pack<double>& b, const Pack<double>& c) {
  return each<Pack<double>>([](auto x, auto y, auto z) HWY_ATTR { return hn::MulAdd(x, y, z); }, a, b, c);
}
/// c − a b, fused where the target has FMA.
HWY_INLINE Pack<double> neg_mul_add(const Pack<double>& a, const Pack<double>& b, const Pack<double>& c) {
  return each<Pack<double>>([](auto x, auto y, auto z) HWY_ATTR { return hn::NegMulAdd(x, y, z); }, a, b, c);
}
/// Natural log for normal positive x (Highway's, ≤ 4 ulp by its statement; subnormals are not
/// handled, none reaches it), and exp (≤ 1 ulp).
HWY_INLINE Pack<double> log(const Pack<double>& a) {
  return each<Pack<double>>([](auto x) HWY_ATTR { return hn::impl::Log<DF, decltype(x), false>(DF(), x); }, a);
}
HWY_INLINE Pack<double> exp(const Pack<double>& a) {
  return each<Pack<double>>([](auto x) HWY_ATTR { return hn::Exp(DF(), x); }, a);
}
/// Exact for |x| < 2^53.
HWY_INLINE Pack<double> to_double(const Pack<std::int64_t>& a) {
  return each<Pack<double>>([](auto x) HWY_ATTR { return hn::ConvertTo(DF(), x); }, a);
}
HWY_INLINE Pack<std::int64_t> to_signed(const Pack<std::uint64_t>& a) {
  return each<Pack<std::int64_t>>([](auto x) HWY_ATTR { return hn::BitCast(hn::RebindToSigned<DF>(), x); }, a);
}
template <int bits>
HWY_INLINE Pack<std::uint64_t> shift_left(const Pack<std::uint64_t>& a) {
  return each<Pack<std::uint64_t>>([](auto x) HWY_ATTR { return hn::ShiftLeft<bits>(x); }, a);
}
template <int bits>
HWY_INLINE Pack<std::uint64_t> shift_right(const Pack<std::uint64_t>& a) {
  return each<Pack<std::uint64_t>>([](auto x) HWY_ATTR { return hn::ShiftRight<bits>(x); }, a);
}
template <int bits>
HWY_INLINE Pack<std::uint64_t> rotate_left(const Pack<std::uint64_t>& a) {
  return each<Pack<std::uint64_t>>([](auto x) HWY_ATTR { return hn::RotateRight<64 - bits>(x); }, a);
}

// Comparisons (ordered: false where a NaN is involved), as lane masks.
template <class T>
HWY_INLINE Mask operator<(const Pack<T>& a, const Pack<T>& b) {
  return each<Mask>([](auto x, auto y) HWY_ATTR { return hn::RebindMask(DF(), hn::Lt(x, y)); }, a, b);
}
template <class T>
HWY_INLINE Mask operator>(const Pack<T>& a, const Pack<T>& b) {
  return b < a;
}
HWY_INLINE Mask operator<=(const Pack<double>& a, const Pack<double>& b) {
  return each<Mask>([](auto x, auto y) HWY_ATTR { return hn::Le(x, y); }, a, b);
}
HWY_INLINE Mask operator>=(const Pack<double>& a, const Pack<double>& b) {
  return b <= a;
}
HWY_INLINE Mask operator==(const Pack<double>& a, const Pack<double>& b) {
  return each<Mask>([](auto x, auto y) HWY_ATTR { return hn::Eq(x, y); }, a, b);
}
HWY_INLINE Mask operator!=(const Pack<double>& a, const Pack<double>& b) {
  return each<Mask>([](auto x, auto y) HWY_ATTR { return hn::Ne(x, y); }, a, b);
}
HWY_INLINE Mask operator&(const Mask& a, const Mask& b) {
  return each<Mask>([](auto x, auto y) HWY_ATTR { return hn::And(x, y); }, a, b);
}
HWY_INLINE Mask operator|(const Mask& a, const Mask& b) {
  return each<Mask>([](auto x, auto y) HWY_ATTR { return hn::Or(x, y); }, a, b);
}
/// The lanes of b that are not in a.
HWY_INLINE Mask and_not(const Mask& a, const Mask& b) {
  return each<Mask>([](auto x, auto y) HWY_ATTR { return hn::AndNot(x, y); }, a, b);
}
HWY_INLINE Mask operator!(const Mask& a) {
  return each<Mask>([](auto x) HWY_ATTR { return hn::Not(x); }, a);
}
/// m ? yes : no, lane by lane.
template <class T>
HWY_INLINE Pack<T> select(const Mask& m, const Pack<T>& yes, const Pack<T>& no) {
  Pack<T> r;
  for (std::size_t k = 0; k < K; ++k)
    r.v[k] = hn::IfThenElse(hn::RebindMask(typename Pack<T>::D(), m.v[k]), yes.v[k], no.v[k]);
  return r;
}
HWY_INLINE bool none(const Mask& m) {
  for (std::size_t k = 0; k < K; ++k)
    if (!hn::AllFalse(DF(), m.v[k])) return false;
  return true;
}
HWY_INLINE std::size_t count(const Mask& m) {
  std::size_t n = 0;
  for (std::size_t k = 0; k < K; ++k) n += hn::CountTrue(DF(), m.v[k]);
  return n;
}
/// Bit l for lane l, and back.
HWY_INLINE unsigned bits(const Mask& m) {
  unsigned r = 0;
  for (std::size_t k = 0; k < K; ++k) {
    std::uint8_t byte[8] = {};
    hn::StoreMaskBits(DF(), m.v[k], byte);
    r |= static_cast<unsigned>(byte[0]) << (k * N);
  }
  return r;
}
HWY_INLINE Mask mask(unsigned lane_bits) {
  Mask r;
  for (std::size_t k = 0; k < K; ++k) {
    const std::uint8_t byte[8] = {static_cast<std::uint8_t>(lane_bits >> (k * N))};
    r.v[k] = hn::LoadMaskBits(DF(), byte);
  }
  return r;
}

/// base[i] and base[i + 1] in every lane (neighbouring cells of a table): gathers with 8 lanes a
/// vector; with 4 or 2, one 16-byte load per lane and a transpose (faster there than gathers).
class Pairs {
 public:
  explicit Pairs(const Pack<std::int64_t>& i) : i_(i) { store(i, index_); }
  void load(const double* base, Pack<double>& at, Pack<double>& next) const {
    for (std::size_t k = 0; k < K; ++k) load_vector<N>(base, k, at.v[k], next.v[k]);
  }

 private:
  template <std::size_t n>  // a template: only n's branch is compiled
  void load_vector(const double* base, std::size_t k, hn::Vec<DF>& at, hn::Vec<DF>& next) const {
    const hn::CappedTag<double, n> d;  // DF
    const std::int64_t* index = index_ + k * n;
    if constexpr (n == 4) {
      const hn::Half<decltype(d)> half;
      const auto low = hn::Combine(d, hn::LoadU(half, base + index[2]), hn::LoadU(half, base + index[0]));
      const auto high = hn::Combine(d, hn::LoadU(half, base + index[3]), hn::LoadU(half, base + index[1]));
      at = hn::InterleaveLower(d, low, high);
      next = hn::InterleaveUpper(d, low, high);
    } else if constexpr (n == 2) {
      const auto first = hn::LoadU(d, base + index[0]), second = hn::LoadU(d, base + index[1]);
      at = hn::InterleaveLower(d, first, second);
      next = hn::InterleaveUpper(d, first, second);
    } else {
      at = hn::GatherIndex(d, base, i_.v[k]);
      next = hn::GatherIndex(d, base + 1, i_.v[k]);
    }
  }
  Pack<std::int64_t> i_;
  alignas(64) std::int64_t index_[lanes];
};

}  // namespace coldblast::kinetic::HWY_NAMESPACE::pack
HWY_AFTER_NAMESPACE();
#endif  // a target with a kernel
#endif  // toggling include guard
