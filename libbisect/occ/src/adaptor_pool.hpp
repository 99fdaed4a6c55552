// Per-thread copies of one OpenCASCADE adaptor, so that the pieces of one face can be meshed on
// several threads at once.
//
// Why: GeomAdaptor_Surface and GeomAdaptor_Curve (and the BRepAdaptor_* and Geom2dAdaptor_Curve
// built on them) keep the polynomial coefficients of the last B-spline span they evaluated in a
// mutable cache (GeomAdaptor_Surface.hxx: "these evaluations are not thread-safe"); nested
// evaluators of offset surfaces and surfaces of revolution or extrusion hold such adaptors of
// their basis too. ShallowCopy() (OCCT 7.6) makes an adaptor over the same geometry with caches
// of its own, nested ones included. The Geom_* objects themselves are read-only once built
// (Geom_BSplineSurface::D0 calls BSplSLib with stack buffers), so copies may share them.
//
// A pool holds a few such copies; a thread takes the slot its thread number points at (so each
// thread keeps the cache of its own span warm), the next free one when that is taken, or a fresh
// copy when all are. Taking and giving back a slot is one atomic exchange each.
#pragma once
#include <Standard_Handle.hxx>

#include <array>
#include <atomic>

namespace bisect::occ {

// The small number of this thread, handed out in order of first use.
inline unsigned thread_number() {
  static std::atomic<unsigned> next{0};
  thread_local const unsigned mine = next.fetch_add(1, std::memory_order_relaxed);
  return mine;
}

template <class Adaptor>  // Adaptor3d_Surface, Adaptor3d_Curve or Adaptor2d_Curve2d
class AdaptorPool {
 public:
  static constexpr unsigned kSlots = 8;

  explicit AdaptorPool(Handle(Adaptor) prototype) : prototype_(std::move(prototype)) {
    for (auto& b : busy_) b.store(false, std::memory_order_relaxed);
  }
  AdaptorPool(const AdaptorPool&) = delete;
  AdaptorPool& operator=(const AdaptorPool&) = delete;

  // The adaptor of one evaluation; gives its slot back when it goes.
  class Lease {
   public:
    Lease(const AdaptorPool* pool, int slot, Handle(Adaptor) own) : pool_(pool), slot_(slot), own_(std::move(own)) {}
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;
    ~Lease() {
      if (slot_ >= 0) pool_->busy_[slot_].store(false, std::memory_order_release);
    }
    const Adaptor& operator*() const { return slot_ >= 0 ? *pool_->slots_[slot_] : *own_; }
    const Adaptor* operator->() const { return &**this; }

   private:
    const AdaptorPool* pool_;
    int slot_;
    Handle(Adaptor) own_;  // when every slot was taken
  };

  Lease acquire() const {
    const unsigned first = thread_number() % kSlots;
    for (unsigned i = 0; i < kSlots; ++i) {
      const unsigned s = (first + i) % kSlots;
      if (busy_[s].exchange(true, std::memory_order_acquire)) continue;
      // only the holder of the slot's flag touches the slot, so creating it here is safe
      if (slots_[s].IsNull()) slots_[s] = prototype_->ShallowCopy();
      return Lease(this, static_cast<int>(s), Handle(Adaptor)());
    }
    return Lease(this, -1, prototype_->ShallowCopy());
  }

 private:
  Handle(Adaptor) prototype_;
  mutable std::array<std::atomic<bool>, kSlots> busy_;
  mutable std::array<Handle(Adaptor), kSlots> slots_;
};

}  // namespace bisect::occ
