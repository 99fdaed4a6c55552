// A minimal signed big integer (sign and magnitude, 32-bit limbs), internal to libbisect.
//
// Why it exists: expansion arithmetic is exact only while every product stays inside the
// double exponent range. A predicate whose coordinates span more than about 2^400 in magnitude
// (say 1e200 next to 1e-200) has determinant terms that no scaling brings into that range. The
// predicates then convert the coordinates to integers (each double is an integer times a power
// of two, and all are brought to the smallest power) and evaluate the determinant here. Such
// inputs are practically nonexistent, so this is simple schoolbook code, not fast code.
#pragma once
#include <cstdint>
#include <cstring>
#include <vector>

namespace bisect::geom::bigint {

class BigInt {
 public:
  BigInt() = default;

  // The exact integer x * 2^-shift_exp, where x is a finite double whose lowest set bit is at
  // or above 2^shift_exp (checked by the caller).
  static BigInt from_double(double x, int shift_exp) {
    BigInt r;
    if (x == 0.0) return r;
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    const int biased = static_cast<int>((bits >> 52) & 0x7ff);
    std::uint64_t mant = bits & ((std::uint64_t{1} << 52) - 1);
    int unit = -1074;  // x = mant * 2^unit
    if (biased != 0) {
      mant |= std::uint64_t{1} << 52;
      unit = biased - 1075;
    }
    while ((mant & 1) == 0) {
      mant >>= 1;
      ++unit;
    }
    const int shift = unit - shift_exp;  // >= 0
    r.sign_ = (bits >> 63) ? -1 : 1;
    const int limb_shift = shift / 32, bit_shift = shift % 32;
    r.mag_.assign(limb_shift, 0u);
    // mant < 2^53, shifted by < 32 bits: fits in three limbs.
    const unsigned __int128 v = static_cast<unsigned __int128>(mant) << bit_shift;
    r.mag_.push_back(static_cast<std::uint32_t>(v));
    r.mag_.push_back(static_cast<std::uint32_t>(v >> 32));
    r.mag_.push_back(static_cast<std::uint32_t>(v >> 64));
    r.trim();
    return r;
  }

  int sign() const { return sign_; }

  friend BigInt operator+(const BigInt& a, const BigInt& b) { return add(a, b, b.sign_); }
  friend BigInt operator-(const BigInt& a, const BigInt& b) { return add(a, b, -b.sign_); }
  friend BigInt operator*(const BigInt& a, const BigInt& b) {
    BigInt r;
    if (a.sign_ == 0 || b.sign_ == 0) return r;
    r.sign_ = a.sign_ * b.sign_;
    r.mag_.assign(a.mag_.size() + b.mag_.size(), 0u);
    for (std::size_t i = 0; i < a.mag_.size(); ++i) {
      std::uint64_t carry = 0;
      for (std::size_t j = 0; j < b.mag_.size(); ++j) {
        const std::uint64_t t =
            static_cast<std::uint64_t>(a.mag_[i]) * b.mag_[j] + r.mag_[i + j] + carry;
        r.mag_[i + j] = static_cast<std::uint32_t>(t);
        carry = t >> 32;
      }
      r.mag_[i + b.mag_.size()] = static_cast<std::uint32_t>(carry);
    }
    r.trim();
    return r;
  }

 private:
  int sign_ = 0;                    // -1, 0 or +1; 0 exactly when mag_ is empty
  std::vector<std::uint32_t> mag_;  // little-endian limbs, no leading zero limb

  void trim() {
    while (!mag_.empty() && mag_.back() == 0) mag_.pop_back();
    if (mag_.empty()) sign_ = 0;
  }

  static int compare_mag(const BigInt& a, const BigInt& b) {
    if (a.mag_.size() != b.mag_.size()) return a.mag_.size() < b.mag_.size() ? -1 : 1;
    for (std::size_t i = a.mag_.size(); i-- > 0;)
      if (a.mag_[i] != b.mag_[i]) return a.mag_[i] < b.mag_[i] ? -1 : 1;
    return 0;
  }

  // a + (b with its sign replaced by bsign).
  static BigInt add(const BigInt& a, const BigInt& b, int bsign) {
    if (bsign == 0) return a;
    if (a.sign_ == 0) {
      BigInt r = b;
      r.sign_ = bsign;
      return r;
    }
    BigInt r;
    if (a.sign_ == bsign) {
      const BigInt& big = a.mag_.size() >= b.mag_.size() ? a : b;
      const BigInt& small = a.mag_.size() >= b.mag_.size() ? b : a;
      r.sign_ = bsign;
      r.mag_ = big.mag_;
      r.mag_.push_back(0u);
      std::uint64_t carry = 0;
      for (std::size_t i = 0; i < r.mag_.size(); ++i) {
        const std::uint64_t t = static_cast<std::uint64_t>(r.mag_[i]) +
                                (i < small.mag_.size() ? small.mag_[i] : 0u) + carry;
        r.mag_[i] = static_cast<std::uint32_t>(t);
        carry = t >> 32;
      }
    } else {
      const int c = compare_mag(a, b);
      if (c == 0) return r;
      const BigInt& big = c > 0 ? a : b;
      const BigInt& small = c > 0 ? b : a;
      r.sign_ = c > 0 ? a.sign_ : bsign;
      r.mag_ = big.mag_;
      std::int64_t borrow = 0;
      for (std::size_t i = 0; i < r.mag_.size(); ++i) {
        std::int64_t t = static_cast<std::int64_t>(r.mag_[i]) -
                         (i < small.mag_.size() ? small.mag_[i] : 0u) - borrow;
        borrow = t < 0 ? 1 : 0;
        if (t < 0) t += std::int64_t{1} << 32;
        r.mag_[i] = static_cast<std::uint32_t>(t);
      }
    }
    r.trim();
    return r;
  }
};

}  // namespace bisect::geom::bigint
