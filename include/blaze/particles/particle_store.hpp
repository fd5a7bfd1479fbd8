// The owning SoA particle store of one memory space, and the trivially copyable view kernels take.
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>
#include "blaze/exec/buffer.hpp"
#include "blaze/exec/launch.hpp"
#include "blaze/particles/energy_ledger.hpp"
#include "blaze/particles/particle_state.hpp"
#include "blaze/particles/soa.hpp"

namespace blaze {

template <class Real>
struct ParticleView {
  Index n;  // active particles: [0, n)
  Vec3Field<Real> position, velocity, angular_velocity, force, torque;
  // a(t) and T(t) of the last force evaluation, for integrators that keep them; null otherwise.
  Vec3Field<Real> acceleration_prev, torque_prev;
  QuatField<Real> orientation;
  const Real* radius;
  const Real* inv_mass;
  const Real* inv_inertia;  // 1/(kg m^2), isotropic bodies (spheres); others use their shape table
  const std::uint8_t* material;
  const std::uint8_t* type;
  const Index* id;
  // Deepest overlap / radius of each particle's contacts since the last reset (Features::monitor);
  // null otherwise.
  Real* penetration;
  // The particle's energy accounts since the last reset (J: the moving walls' work, the energy
  // its contacts dissipated by class; energy_ledger.hpp): a world that moves, or when asked.
  EnergyLedger<Real> ledger;
};

template <class T>
struct Gather {
  const T* src;
  T* dst;
  const Index* perm;
  BLAZE_HD void operator()(Index i) const { dst[i] = src[perm[i]]; }
};
// Up to kMaxFields arrays gathered by one permutation in one pass, dst[a][i] = src[a][perm[i]]:
// ParticleStore::permute moves every array a rebuild reorders in one launch, where a launch per
// array (some 35) took 0.14 ms of a 242-ball mill's 0.22 ms rebuild on an H100.
template <class T>
struct GatherFields {
  static constexpr int kMaxFields = 40;
  const T* src[kMaxFields];
  T* dst[kMaxFields];
  int count;
  const Index* perm;
  BLAZE_HD void operator()(Index i) const {
    const Index j = perm[i];
    for (int a = 0; a < count; ++a) dst[a][i] = src[a][j];
  }
};
template <class T>
struct Scatter {
  const T* src;
  T* dst;
  const Index* perm;
  BLAZE_HD void operator()(Index i) const { dst[perm[i]] = src[i]; }
};

// Every array of a ParticleStore that carries state across steps, on the host, raw (inverse mass
// and inertia as stored, so a round trip is exact) and in the store's order: what a checkpoint
// holds for a bitwise restart. Force and torque are included: some integrators read them before
// the next evaluation.
template <class Real>
struct StoreSnapshot {
  static constexpr std::size_t kRadiusField = 25;  // the radius array's place in `reals`
  static constexpr std::size_t kPositionField = 0, kVelocityField = 3;  // x, y, z from there
  static constexpr std::size_t kInverseMassField = 26;
  std::vector<std::vector<Real>> reals;  // ParticleStore::real_fields() order; empty where unused
  std::vector<std::uint8_t> material, type;
  std::vector<Index> id;
  // Periodic runs: each particle's image counts (x, y, z per particle; the times it was wrapped
  // across each periodic axis, so x + image L is its unwrapped position); empty otherwise.
  std::vector<Index> image;
};

template <class Real, class Space>
class ParticleStore {
 public:
  static constexpr std::size_t kRadiusField = StoreSnapshot<Real>::kRadiusField;
  // ledger: keep each particle's energy accounts (energy_ledger.hpp); thesis_estimate: and the
  // thesis's power estimate beside them.
  void upload(const ParticleState<Real>& s, bool keep_previous_forces, bool monitor = false, bool ledger = false,
              bool thesis_estimate = false) {
    s.check_consistent();
    n_ = static_cast<Index>(s.size());
    with_previous_ = keep_previous_forces, with_penetration_ = monitor, with_ledger_ = ledger;
    with_thesis_ = ledger && thesis_estimate;
    std::vector<Real> inv_m(n_), inv_i(n_);
    for (Index i = 0; i < n_; ++i) {
      inv_m[i] = Real(1) / s.mass[i];
      inv_i[i] = Real(1) / s.inertia[i].x;
    }
    upload_vec3(position_, s.position);
    upload_vec3(velocity_, s.velocity);
    upload_vec3(angular_velocity_, s.angular_velocity);
    for (auto* f : {&force_, &torque_}) resize3(*f, n_);
    for (auto* f : {&acceleration_prev_, &torque_prev_}) {
      resize3(*f, keep_previous_forces ? n_ : 0);
      if (keep_previous_forces) upload_vec3(*f, std::vector<Vec3<Real>>(n_, Vec3<Real>{0, 0, 0}));
    }
    std::vector<Real> qw(n_), qx(n_), qy(n_), qz(n_);
    for (Index i = 0; i < n_; ++i) {
      qw[i] = s.orientation[i].w; qx[i] = s.orientation[i].x;
      qy[i] = s.orientation[i].y; qz[i] = s.orientation[i].z;
    }
    from_host(orientation_[0], qw); from_host(orientation_[1], qx);
    from_host(orientation_[2], qy); from_host(orientation_[3], qz);
    from_host(radius_, s.radius);
    from_host(inv_mass_, inv_m);
    from_host(inv_inertia_, inv_i);
    from_host(material_, s.material);
    from_host(type_, s.type);
    from_host(id_, s.id);
    from_host(penetration_, std::vector<Real>(monitor ? n_ : 0, Real(0)));
    for (auto& c : ledger_) from_host(c, std::vector<Real>(ledger ? n_ : 0, Real(0)));
    lay_class_sums(ledger ? static_cast<std::size_t>(n_) : 0);
    from_host(thesis_, std::vector<Real>(ledger && thesis_estimate ? n_ : 0, Real(0)));
  }

  // Adds `s`'s particles after the active ones (a feeder's insertion, pipeline/feeder.hpp): their
  // state as given, force, torque and every account zero. Buffers grow by half again when full
  // (Buffer::grow_keep), so a feed of N particles allocates O(log N) times.
  void append(const ParticleState<Real>& s) {
    s.check_consistent();
    const std::size_t n = static_cast<std::size_t>(n_), m = s.size(), total = n + m;
    if (m == 0) return;
    std::vector<Real> c(m);
    auto put3 = [&](Field3& f, const std::vector<Vec3<Real>>& v) {
      for (int d = 0; d < 3; ++d) {
        for (std::size_t k = 0; k < m; ++k) c[k] = d == 0 ? v[k].x : d == 1 ? v[k].y : v[k].z;
        put(f[d], c, n, total);
      }
    };
    // fields that start at zero are zeroed where they live (no host array to copy in)
    auto zero3 = [&](Field3& f) {
      for (auto& b : f) put_zero(b, n, total);
    };
    put3(position_, s.position);
    put3(velocity_, s.velocity);
    put3(angular_velocity_, s.angular_velocity);
    zero3(force_);
    zero3(torque_);
    if (with_previous_) zero3(acceleration_prev_), zero3(torque_prev_);
    for (int q = 0; q < 4; ++q) {
      for (std::size_t k = 0; k < m; ++k) {
        const Quat<Real>& o = s.orientation[k];
        c[k] = q == 0 ? o.w : q == 1 ? o.x : q == 2 ? o.y : o.z;
      }
      put(orientation_[q], c, n, total);
    }
    put(radius_, s.radius, n, total);
    for (std::size_t k = 0; k < m; ++k) c[k] = Real(1) / s.mass[k];
    put(inv_mass_, c, n, total);
    for (std::size_t k = 0; k < m; ++k) c[k] = Real(1) / s.inertia[k].x;
    put(inv_inertia_, c, n, total);
    put(material_, s.material, n, total);
    put(type_, s.type, n, total);
    put(id_, s.id, n, total);
    if (with_penetration_) put_zero(penetration_, n, total);
    if (with_ledger_)
      for (auto& l : ledger_) put_zero(l, n, total);
    if (with_thesis_) put_zero(thesis_, n, total);
    if (with_images_)
      for (auto& axis : image_) put_zero(axis, n, total);
    if (with_ledger_ && class_sums_.size() < kClassSumReals * total)  // per-step scratch, column stride: laid anew
      lay_class_sums(std::max(total, n + n / 2));
    n_ = static_cast<Index>(total);
  }

  // The active particles [0, n) back on the host, in the store's current (sorted) order.
  // `inertia` is filled by the caller's shape policy from inverse_inertia() and `type`.
  ParticleState<Real> download() const {
    ParticleState<Real> s;
    s.position = download_vec3(position_);
    s.velocity = download_vec3(velocity_);
    s.angular_velocity = download_vec3(angular_velocity_);
    const auto qw = to_host(orientation_[0], n_), qx = to_host(orientation_[1], n_),
               qy = to_host(orientation_[2], n_), qz = to_host(orientation_[3], n_);
    s.orientation.resize(n_);
    for (Index i = 0; i < n_; ++i) s.orientation[i] = {qw[i], qx[i], qy[i], qz[i]};
    s.radius = to_host(radius_, n_);
    s.mass = to_host(inv_mass_, n_);
    for (auto& m : s.mass) m = Real(1) / m;
    s.material = to_host(material_, n_);
    s.type = to_host(type_, n_);
    s.inertia.resize(n_);
    s.id = to_host(id_, n_);
    return s;
  }

  std::vector<Real> download_inverse_inertia() const { return to_host(inv_inertia_, n_); }
  std::vector<Vec3<Real>> download_force() const { return download_vec3(force_); }
  std::vector<Vec3<Real>> download_torque() const { return download_vec3(torque_); }
  std::vector<Index> download_id() const { return to_host(id_, n_); }
  std::vector<Real> download_penetration() const { return to_host(penetration_, penetration_.size() ? n_ : 0); }
  void reset_penetration() {
    if (penetration_.size()) for_each(Space{}, n_, Fill<Real>{penetration_.data(), Real(0)});
  }
  void reset_ledger() {
    for (auto& c : ledger_)
      if (c.size()) for_each(Space{}, n_, Fill<Real>{c.data(), Real(0)});
    if (thesis_.size()) for_each(Space{}, n_, Fill<Real>{thesis_.data(), Real(0)});
  }
  // A restored run that keeps the accounts but whose checkpoint had none, or only the drive's
  // (zero from here).
  void keep_ledger(bool thesis_estimate = false) {
    for (auto& c : ledger_)
      if (c.size() < static_cast<std::size_t>(n_)) from_host(c, std::vector<Real>(n_, Real(0)));
    lay_class_sums(static_cast<std::size_t>(n_));
    if (!thesis_estimate) thesis_.resize(0);  // (a snapshot's, or zero from here)
    else if (thesis_.size() < static_cast<std::size_t>(n_)) from_host(thesis_, std::vector<Real>(n_, Real(0)));
    with_ledger_ = true, with_thesis_ = thesis_estimate;
  }
  bool keeps_ledger() const { return with_ledger_; }
  // A restored store keeps the optional fields its run keeps (a snapshot of no particles has
  // none to tell by): the previous forces and the penetration monitor, zero where missing.
  void keep_fields(bool keep_previous_forces, bool monitor) {
    with_previous_ = keep_previous_forces, with_penetration_ = monitor;
    const std::vector<Real> zeros(static_cast<std::size_t>(n_), Real(0));
    if (keep_previous_forces)
      for (auto* f : {&acceleration_prev_, &torque_prev_})
        for (auto& c : *f)
          if (c.size() < zeros.size()) from_host(c, zeros);
    if (monitor && penetration_.size() < zeros.size()) from_host(penetration_, zeros);
  }

  ParticleView<Real> view() {
    return {n_, field(position_), field(velocity_), field(angular_velocity_), field(force_),
            field(torque_), field(acceleration_prev_), field(torque_prev_),
            {orientation_[0].data(), orientation_[1].data(), orientation_[2].data(), orientation_[3].data()},
            radius_.data(), inv_mass_.data(), inv_inertia_.data(), material_.data(), type_.data(), id_.data(),
            penetration_.size() ? penetration_.data() : nullptr, ledger_view()};
  }

  using Snapshot = StoreSnapshot<Real>;
  Snapshot snapshot() const {
    Snapshot s;
    for (const auto* f : const_cast<ParticleStore*>(this)->real_fields()) s.reals.push_back(to_host(*f, f->size() ? n_ : 0));
    s.material = to_host(material_, n_);
    s.type = to_host(type_, n_);
    s.id = to_host(id_, n_);
    s.image = download_images();
    return s;
  }
  void restore(const Snapshot& s) {
    const auto fields = real_fields();
    // the energy accounts and the thesis's estimate are the last fields: a snapshot from before the
    // estimate was kept lacks it, one from before the dissipation columns holds only the drive's,
    // one from before moving walls none
    const std::size_t ledger_at = fields.size() - 1 - kLedgerColumns;
    if (s.reals.size() != fields.size() && s.reals.size() != fields.size() - 1 && s.reals.size() != ledger_at + 1 &&
        s.reals.size() != ledger_at)
      throw std::invalid_argument("particle snapshot: wrong number of fields");
    n_ = static_cast<Index>(s.id.size());
    for (auto& c : ledger_) c.resize(0);
    lay_class_sums(0);
    thesis_.resize(0);
    for (std::size_t k = 0; k < s.reals.size(); ++k) {
      if (!s.reals[k].empty() && s.reals[k].size() != s.id.size())
        throw std::invalid_argument("particle snapshot: field " + std::to_string(k) + " has the wrong length");
      from_host(*fields[k], s.reals[k]);
    }
    from_host(material_, s.material);
    from_host(type_, s.type);
    from_host(id_, s.id);
    if (!s.image.empty()) {
      if (s.image.size() != 3 * s.id.size()) throw std::invalid_argument("particle snapshot: the image counts have the wrong length");
      for (int d = 0; d < 3; ++d) {
        std::vector<Index> c(s.id.size());
        for (std::size_t i = 0; i < c.size(); ++i) c[i] = s.image[3 * i + static_cast<std::size_t>(d)];
        from_host(image_[d], c);
      }
      with_images_ = true;
    }
  }

  // The rows `which` (store indices, on the space) of every real array kept, array after array
  // (count values each): what a ghost's copy needs of its particle each step (issue 21; the
  // distributed driver); upload_rows() writes such rows back at other indices.
  std::size_t kept_real_fields() {
    std::size_t k = 0;
    for (auto* f : real_fields()) k += f->size() > 0;
    return k;
  }
  void download_rows(const Index* which, Index count, std::vector<Real>& out) {
    out.resize(kept_real_fields() * static_cast<std::size_t>(count));
    rows_.ensure(out.size());
    std::size_t at = 0;
    for (auto* f : real_fields()) {
      if (!f->size()) continue;
      for_each(Space{}, count, Gather<Real>{f->data(), rows_.data() + at, which});
      at += static_cast<std::size_t>(count);
    }
    copy_n(rows_.data(), out.size(), out.data(), Space{}, Host{});
  }
  void upload_rows(const Index* which, Index count, const std::vector<Real>& in) {
    if (in.size() != kept_real_fields() * static_cast<std::size_t>(count))
      throw std::invalid_argument("particle store: " + std::to_string(in.size()) + " row values for " + std::to_string(count) + " rows");
    rows_.ensure(in.size());
    copy_n(in.data(), in.size(), rows_.data(), Host{}, Space{});
    std::size_t at = 0;
    for (auto* f : real_fields()) {
      if (!f->size()) continue;
      for_each(Space{}, count, Scatter<Real>{rows_.data() + at, f->data(), which});
      at += static_cast<std::size_t>(count);
    }
  }

  // Periodic runs keep each particle's image counts (zero for those that have none yet), permuted
  // with the particles and in snapshots.
  void keep_images() {
    with_images_ = true;
    for (auto& c : image_)
      if (c.size() < static_cast<std::size_t>(n_)) from_host(c, std::vector<Index>(static_cast<std::size_t>(n_), 0));
  }
  bool keeps_images() const { return with_images_; }
  Index* image(int axis) { return with_images_ ? image_[axis].data() : nullptr; }
  // The image counts, x, y, z per particle in the store's order (empty unless kept).
  std::vector<Index> download_images() const {
    std::vector<Index> out;
    if (!with_images_) return out;
    out.resize(3 * static_cast<std::size_t>(n_));
    for (int d = 0; d < 3; ++d) {
      const std::vector<Index> c = to_host(image_[d], n_);
      for (std::size_t i = 0; i < c.size(); ++i) out[3 * i + static_cast<std::size_t>(d)] = c[i];
    }
    return out;
  }

  // This store becomes a copy of `src`'s state as download() reads it (positions, velocities,
  // orientations, radii, masses, inertias, materials, types, ids), copied within the space; the
  // force, torque and scratch arrays stay empty.
  void copy_state_from(const ParticleStore& src) {
    n_ = src.n_;
    const std::size_t n = static_cast<std::size_t>(n_);
    for (int d = 0; d < 3; ++d) {
      copy_field(position_[d], src.position_[d], n);
      copy_field(velocity_[d], src.velocity_[d], n);
      copy_field(angular_velocity_[d], src.angular_velocity_[d], n);
    }
    for (int c = 0; c < 4; ++c) copy_field(orientation_[c], src.orientation_[c], n);
    copy_field(radius_, src.radius_, n);
    copy_field(inv_mass_, src.inv_mass_, n);
    copy_field(inv_inertia_, src.inv_inertia_, n);
    copy_field(material_, src.material_, n);
    copy_field(type_, src.type_, n);
    copy_field(id_, src.id_, n);
  }

  Index size() const { return n_; }
  // Drops the particles [n, size) (they were sorted to the end).
  void truncate(Index n) { n_ = n; }

  // Puts particle perm[i] at position i in every field that carries state across steps.
  // Force and torque are recomputed before they are read, so they are moved only on request (a
  // rebuild between steps, for a checkpoint).
  // The most bytes that permute()'s spare arrays hold (one array at least): with room for all of
  // them a reorder is one launch, without it a launch per array (kSpareBytes by default).
  void limit_spares(std::size_t bytes) { spare_bytes_ = bytes; }
  void permute(const Index* perm, bool with_forces = false) {
    std::vector<Buffer<Real, Space>*> reals;
    for (auto* f : real_fields()) {
      const bool force = f == &force_[0] || f == &force_[1] || f == &force_[2] || f == &torque_[0] || f == &torque_[1] || f == &torque_[2];
      if (f->size() && (with_forces || !force)) reals.push_back(f);
    }
    gather_fields(reals, spare_real_, perm);
    gather_fields<std::uint8_t>({&material_, &type_}, spare_u8_, perm);
    std::vector<Buffer<Index, Space>*> indices{&id_};
    if (with_images_)
      for (auto& c : image_) indices.push_back(&c);
    gather_fields(indices, spare_index_, perm);
  }

  // Bytes held per particle (for benchmarks).
  std::size_t bytes() const {
    std::size_t b = 0;
    for (const auto* f : {&position_, &velocity_, &angular_velocity_, &force_, &torque_, &acceleration_prev_, &torque_prev_})
      for (const auto& c : *f) b += c.size() * sizeof(Real);
    for (const auto& c : orientation_) b += c.size() * sizeof(Real);
    b += (radius_.size() + inv_mass_.size() + inv_inertia_.size() + penetration_.size()) * sizeof(Real);
    for (const auto& c : spare_real_) b += c.size() * sizeof(Real);
    for (const auto& c : spare_u8_) b += c.size();
    for (const auto& c : spare_index_) b += c.size() * sizeof(Index);
    for (const auto& c : ledger_) b += c.size() * sizeof(Real);
    b += (class_sums_.size() + thesis_.size()) * sizeof(Real) + class_mask_.size();
    b += material_.size() + type_.size() + id_.size() * sizeof(Index);
    return b;
  }

 private:
  using Field3 = Buffer<Real, Space>[3];

  EnergyLedger<Real> ledger_view() {
    EnergyLedger<Real> l;
    for (int c = 0; c < kLedgerColumns; ++c) l.column[c] = ledger_[c].size() ? ledger_[c].data() : nullptr;
    l.class_sums = class_sums_.size() ? class_sums_.data() : nullptr;
    l.class_mask = class_mask_.size() ? class_mask_.data() : nullptr;
    l.n = static_cast<Index>(class_sums_.size() / kClassSumReals);  // the stride it was sized with
    l.thesis_estimate = thesis_.size() ? thesis_.data() : nullptr;
    return l;
  }
  static Vec3Field<Real> field(Field3& f) { return {f[0].data(), f[1].data(), f[2].data()}; }
  // The wall classes' per-step sums and their mask for n particles (zero: no class written).
  void lay_class_sums(std::size_t n) {
    from_host(class_sums_, std::vector<Real>(kClassSumReals * n, Real(0)));
    from_host(class_mask_, std::vector<std::uint8_t>(n, 0));
  }
  static void resize3(Field3& f, Index n) {
    for (auto& c : f) c.resize(n);
  }
  void upload_vec3(Field3& f, const std::vector<Vec3<Real>>& v) {
    std::vector<Real> c(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) c[i] = v[i].x;
    from_host(f[0], c);
    for (std::size_t i = 0; i < v.size(); ++i) c[i] = v[i].y;
    from_host(f[1], c);
    for (std::size_t i = 0; i < v.size(); ++i) c[i] = v[i].z;
    from_host(f[2], c);
  }
  std::vector<Vec3<Real>> download_vec3(const Field3& f) const {
    const auto x = to_host(f[0], n_), y = to_host(f[1], n_), z = to_host(f[2], n_);
    std::vector<Vec3<Real>> v(n_);
    for (Index i = 0; i < n_; ++i) v[i] = {x[i], y[i], z[i]};
    return v;
  }
  std::vector<Buffer<Real, Space>*> real_fields() {
    std::vector<Buffer<Real, Space>*> f;
    for (auto* v : {&position_, &velocity_, &angular_velocity_, &force_, &torque_, &acceleration_prev_, &torque_prev_})
      for (auto& c : *v) f.push_back(&c);
    for (auto& c : orientation_) f.push_back(&c);
    for (auto* c : {&radius_, &inv_mass_, &inv_inertia_, &penetration_}) f.push_back(c);
    for (auto& c : ledger_) f.push_back(&c);  // last: older snapshots lack some (restore())
    f.push_back(&thesis_);                      // (Features::thesis_power's; absent before stop 39)
    if (f[kRadiusField] != &radius_ || f[Snapshot::kPositionField] != &position_[0] || f[Snapshot::kVelocityField] != &velocity_[0] ||
        f[Snapshot::kInverseMassField] != &inv_mass_)
      throw std::logic_error("ParticleStore: the snapshot's field places are stale");
    return f;
  }
  // b[n, n + v.size()) = v, growing b (keeping [0, n)) when it is shorter than `total`.
  template <class T>
  static void put(Buffer<T, Space>& b, const std::vector<T>& v, std::size_t n, std::size_t total) {
    b.grow_keep(total, n);
    copy_n(v.data(), v.size(), b.data() + n, Host{}, Space{});
  }
  template <class T>
  static void put_zero(Buffer<T, Space>& b, std::size_t n, std::size_t total) {
    b.grow_keep(total, n);
    for_each(Space{}, static_cast<Index>(total - n), Fill<T>{b.data() + n, T(0)});
  }
  template <class T>
  static void copy_field(Buffer<T, Space>& dst, const Buffer<T, Space>& src, std::size_t n) {
    if (dst.size() < n) dst.resize(src.size());
    copy_n(src.data(), n, dst.data(), Space{}, Space{});
  }
  // Each of `fields` becomes fields[perm] over [0, n_), as many per launch as the spare arrays
  // allow: all of them while one array holds no more than spare_bytes_ / kMaxFields, fewer beyond,
  // one at a time from spare_bytes_ an array on (8.4e6 particles in float by default): the spares
  // hold about spare_bytes_, or one array.
  template <class T>
  void gather_fields(const std::vector<Buffer<T, Space>*>& fields, std::vector<Buffer<T, Space>>& spare, const Index* perm) {
    const std::size_t per_launch = arrays_per_launch(spare_bytes_, static_cast<std::size_t>(n_) * sizeof(T), fields.size(),
                                                     GatherFields<T>::kMaxFields);
    if (spare.size() < per_launch) spare.resize(per_launch);
    for (std::size_t a = 0; a < fields.size(); a += per_launch) {
      const std::size_t m = std::min(per_launch, fields.size() - a);
      GatherFields<T> g{};
      g.count = static_cast<int>(m), g.perm = perm;
      for (std::size_t b = 0; b < m; ++b) {
        spare[b].resize(fields[a + b]->size());
        g.src[b] = fields[a + b]->data(), g.dst[b] = spare[b].data();
      }
      for_each(Space{}, n_, g);
      for (std::size_t b = 0; b < m; ++b) fields[a + b]->swap(spare[b]);
    }
  }

  Buffer<Real, Space> rows_;  // download_rows / upload_rows staging
  Index n_ = 0;
  // Which optional fields this store keeps (their buffers are empty while it holds no particle).
  bool with_previous_ = false, with_penetration_ = false, with_ledger_ = false, with_thesis_ = false, with_images_ = false;
  Field3 position_, velocity_, angular_velocity_, force_, torque_, acceleration_prev_, torque_prev_;
  Buffer<Real, Space> orientation_[4];
  Buffer<Real, Space> radius_, inv_mass_, inv_inertia_;
  Buffer<Real, Space> penetration_;  // Features::monitor only
  Buffer<Real, Space> ledger_[kLedgerColumns];  // energy_ledger.hpp; a moving world, or when asked
  Buffer<Real, Space> class_sums_;  // with the ledger: the walls' force and torque per class, this step
  Buffer<std::uint8_t, Space> class_mask_;  // and which classes' sums this step wrote
  Buffer<Real, Space> thesis_;      // with the ledger and Features::thesis_power: sum |F_diss| |V| dt
  Buffer<std::uint8_t, Space> material_, type_;
  Buffer<Index, Space> id_;
  Buffer<Index, Space> image_[3];  // periodic runs: image counts per axis (keep_images())
  std::size_t spare_bytes_ = kSpareBytes;  // limit_spares()
  // permute()'s spare arrays (gather_fields)
  std::vector<Buffer<Real, Space>> spare_real_;
  std::vector<Buffer<std::uint8_t, Space>> spare_u8_;
  std::vector<Buffer<Index, Space>> spare_index_;
};

}  // namespace blaze
