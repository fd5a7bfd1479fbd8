// Contact-type frequency of cubes (thesis section 3.4.3, Fig 3.27; scenes after sections 3.4.1-3.4.2).
//
// Kind of a contact: the separating-axis kernel (shapes/polyhedron_shape.hpp) takes the axis of least
// penetration; a face normal makes it vertex-face (the thesis's Type 1: vertex-face or face-face),
// the cross product of an edge pair makes it edge-edge (Type 2). Simulation::contact_counts()
// returns both counts of the last force evaluation, over particle-particle contacts only. Wall and
// drum contacts are not counted: they are vertex-face by construction (thesis section 3.2.1: the
// drum is an internal object, a wall a plane).
//
// Closed form for random first touches (integral geometry). Two convex polyhedra A and B touch on
// a facet of the Minkowski difference A - B: A's faces (total area S_A), B's faces (S_B) and one
// parallelogram |e_A x e_B| per edge pair whose Gauss-map arcs cross (the edge-edge contacts).
// Over uniformly random relative orientations the rotation mean of the surface area is
//   E[S(A - rho B)] = S_A + S_B + M_A M_B / (2 pi)      (Hadwiger's rotation-sum formula; check:
//                                                      two spheres, M = 4 pi r, give 4 pi (r+s)^2)
// with M = (1/2) sum_edges L_e (pi - interior dihedral angle) the integrated mean curvature (m).
// A random line hits a facet with probability proportional to its area (Cauchy), so a first touch
// from a uniformly random direction and impact point is edge-edge with probability
//   P_ee = (M_A M_B / 2 pi) / (S_A + S_B + M_A M_B / 2 pi).
// Cube of edge a: S = 6 a^2, M = 12 a (pi/2) / 2 = 3 pi a, so P_ee = 9 pi / (24 + 9 pi) = 0.5409.
//
// The thesis reports at most 10% edge-edge for a gravity packing (a), slightly more in a drum
// (b), and up to 30% in a drum where an initial velocity makes the cubes hit the wall (c). Its
// scenes start from aligned, symmetric grids (Figs 3.19-3.20). Aligned cubes moving in a plane
// only ever pair parallel edges or edges whose cross product is a face normal, so they make no
// edge-edge contact at all (measured: an aligned block in the drum, 0 in 4500 steps), while any
// 3-d disorder (2 degrees of tilt, 2 mm/s of random velocity) brings the share up to ~50%. Here
// all three scenes start from random orientations (as polyhedron_packing does) and the shares
// of the separating-axis kind are held against the random-contact value P_ee.
// The thesis also classifies differently: Type 1 as soon as a vertex of either body is inside the
// other (Algorithm 1), edge-edge only otherwise; that is what its Fig 3.27 counts. The same
// contacts classified by that rule (on the host) give the thesis's picture: first touches still
// 54%, but the box's bed falls from ~45% while it collapses to ~23% at 0.2 s, ~13% at 0.45-0.6 s
// and ~12% (pooled over six beds) at 0.675-0.9 s, ~9% by 1.2 s; the drums stay near 28% over
// 0.4 s (still filling in): most
// separating-axis edge-edge contacts of a bed are nearly flat face contacts whose
// least-penetration axis is an edge pair. The box therefore runs until its bed has settled and
// the bound (below 15%) is asserted by the thesis's rule over the settled phase; the
// separating-axis rows stay beside it, each row saying which classification it uses.
// The kernel's counts are checked against an independent brute-force classification on the host
// (every face normal and every edge-pair cross product, two-sided projections, in Eigen).
#include <boost/test/unit_test.hpp>
#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>
#include "blaze/shapes/polyhedron_shape.hpp"
#include "pipeline/polyhedron_packing.hpp"
#include "blaze/shapes/shape_io.hpp"
#include "verification/report.hpp"
#include "verification/scenes.hpp"
#include "verification/stress_size.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

using Law = LinearLaw<double>;
using Shape = PolyhedronShape<double>;
using Features = FeatureSet<true, true>;
using Sim = Simulation<DefaultSpace, Shape, Law, VelocityVerlet, ContactPointVelocity, Features>;

const char* kCubeFile = "data/shapes/cube.shape";
constexpr double kDensity = 2500;  // kg/m^3

// P_ee of the header for two equal convex polyhedra of surface area s and mean curvature m.
double random_contact_edge_edge(double s, double m) {
  const double mixed = m * m / (2 * kPi);
  return mixed / (2 * s + mixed);
}

// Integrated mean curvature M = (1/2) sum_e L_e (pi - interior dihedral angle), from the shape's
// edges and face normals (the angle between the two outward normals is pi - interior angle).
double mean_curvature_integral(const ConvexShape& c) {
  double m = 0;
  for (const auto& e : c.edges) {
    const double len = (c.vertices[e.v1] - c.vertices[e.v0]).norm();
    const double cosine = std::clamp(c.normals[e.left].dot(c.normals[e.right]), -1.0, 1.0);
    m += 0.5 * len * std::acos(cosine);
  }
  return m;
}

double surface_area(const ConvexShape& c) {
  double s = 0;
  for (const auto& f : c.faces) {
    Eigen::Vector3d a = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < f.size(); ++k) a += c.vertices[f[k]].cross(c.vertices[f[(k + 1) % f.size()]]);
    s += 0.5 * a.norm();
  }
  return s;
}

// ---- independent host classification ---------------------------------------------------------

struct Placed {
  std::vector<Eigen::Vector3d> vertex, normal, edge;
  std::vector<double> offset;  // support of each face plane: normal . x <= offset inside
};

Placed place(const ConvexShape& c, const Vec3<double>& x, const Quat<double>& q) {
  const Eigen::Matrix3d r = Eigen::Quaterniond(q.w, q.x, q.y, q.z).normalized().toRotationMatrix();
  const Eigen::Vector3d t(x.x, x.y, x.z);
  Placed p;
  for (const auto& v : c.vertices) p.vertex.push_back(t + r * v);
  for (const auto& n : c.normals) {
    p.normal.push_back(r * n);
    double h = -std::numeric_limits<double>::infinity();
    for (const auto& v : p.vertex) h = std::max(h, p.normal.back().dot(v));
    p.offset.push_back(h);
  }
  for (const auto& e : c.edges) p.edge.push_back(p.vertex[e.v1] - p.vertex[e.v0]);
  return p;
}

struct HostKinds {
  long vertex_face = 0, edge_edge = 0;
  long ambiguous = 0;  // touching or kind decided by less than the tie margin
  // The same pairs (ties included) by the thesis's rule: vertex-face as soon as a vertex of
  // either body is inside the other, edge-edge otherwise.
  long thesis_vertex_face = 0, thesis_edge_edge = 0;
  void operator+=(const HostKinds& o) {
    vertex_face += o.vertex_face, edge_edge += o.edge_edge, ambiguous += o.ambiguous;
    thesis_vertex_face += o.thesis_vertex_face, thesis_edge_edge += o.thesis_edge_edge;
  }
  double thesis_share() const {
    const long all = thesis_vertex_face + thesis_edge_edge;
    return all > 0 ? static_cast<double>(thesis_edge_edge) / static_cast<double>(all) : 0.0;
  }
};

// Brute-force separating-axis classification of one pair (reach: sum of bounding radii, m).
HostKinds classify(const Placed& a, const Placed& b, double reach) {
  const auto separation = [&](const Eigen::Vector3d& n) {
    double a_lo = 1e300, a_hi = -1e300, b_lo = 1e300, b_hi = -1e300;
    for (const auto& v : a.vertex) a_lo = std::min(a_lo, n.dot(v)), a_hi = std::max(a_hi, n.dot(v));
    for (const auto& v : b.vertex) b_lo = std::min(b_lo, n.dot(v)), b_hi = std::max(b_hi, n.dot(v));
    return std::max(b_lo - a_hi, a_lo - b_hi);
  };
  double face = -1e300, edge = -1e300;
  for (const auto& n : a.normal) face = std::max(face, separation(n));
  for (const auto& n : b.normal) face = std::max(face, separation(n));
  for (const auto& da : a.edge)
    for (const auto& db : b.edge) {
      const Eigen::Vector3d n = da.cross(db);
      // Parallel edges have no cross product of their own; a face axis stands for them.
      if (n.squaredNorm() <= tol::contact_kind_parallel_edges * da.squaredNorm() * db.squaredNorm()) continue;
      edge = std::max(edge, separation(n.normalized()));
    }
  HostKinds k;
  const double best = std::max(face, edge), margin = tol::contact_kind_tie * reach;
  if (best > margin) return k;
  if (std::fabs(best) <= margin || std::fabs(face - edge) <= margin) k.ambiguous = 1;
  else (edge > face ? k.edge_edge : k.vertex_face) = 1;
  const auto contains = [](const Placed& body, const Eigen::Vector3d& v) {
    for (std::size_t f = 0; f < body.normal.size(); ++f)
      if (body.normal[f].dot(v) > body.offset[f]) return false;
    return true;
  };
  bool vertex_inside = false;
  for (const auto& v : b.vertex) vertex_inside = vertex_inside || contains(a, v);
  for (const auto& v : a.vertex) vertex_inside = vertex_inside || contains(b, v);
  (vertex_inside ? k.thesis_vertex_face : k.thesis_edge_edge) = 1;
  return k;
}

// All touching pairs of a state (O(n^2) over bounding spheres: a few hundred cubes).
HostKinds classify_state(const ParticleState<double>& s, const ConvexShape& c) {
  std::vector<Placed> placed;
  for (std::size_t i = 0; i < s.size(); ++i) placed.push_back(place(c, s.position[i], s.orientation[i]));
  HostKinds total;
  const double reach = 2 * c.bounding_radius;
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t j = i + 1; j < s.size(); ++j)
      if (norm2(s.position[j] - s.position[i]) < reach * reach) total += classify(placed[i], placed[j], reach);
  return total;
}

// Labels of the two classifications in the rows.
const std::string kSat = "SAT kind (least-penetration axis): ";
const std::string kRule = "thesis rule (vertex inside: vertex-face): ";

// Kernel counts of the last force evaluation against the host classification of the same state.
void check_against_host(const std::string& case_name, std::pair<long, long> kernel, const HostKinds& host) {
  const std::string source = "brute-force SAT on the host (all face and edge-pair axes)";
  BOOST_TEST_MESSAGE(case_name << ": kernel " << kernel.first << " vertex-face / " << kernel.second << " edge-edge; host "
                               << host.vertex_face << " / " << host.edge_edge << ", " << host.ambiguous
                               << " within the tie margin; thesis rule (edge-edge iff no vertex inside): "
                               << host.thesis_vertex_face << " / " << host.thesis_edge_edge);
  check_near({case_name, kSat + "vertex-face count, kernel vs host (tolerance: pairs within the tie margin)", "-", source},
             static_cast<double>(kernel.first), static_cast<double>(host.vertex_face), static_cast<double>(host.ambiguous));
  check_near({case_name, kSat + "edge-edge count, kernel vs host (tolerance: pairs within the tie margin)", "-", source},
             static_cast<double>(kernel.second), static_cast<double>(host.edge_edge), static_cast<double>(host.ambiguous));
}

// "0.6 s": a run length for the rows' text.
std::string seconds(double t) {
  char text[32];
  std::snprintf(text, sizeof text, "%g s", t);
  return text;
}

Quat<double> random_orientation(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  return normalized(Quat<double>{g(rng), g(rng), g(rng), g(rng)});
}

Vec3<double> random_direction(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  const Vec3<double> u{g(rng), g(rng), g(rng)};
  return u * (1.0 / norm(u));
}

// ---- the scenes of Fig 3.27 -----------------------------------------------------------------

struct Material {
  Law law;
  double dt;  // s
};

// Contact law of the scenes: stiffness tol::kind_scene_stiffness, restitution 0.3, mu 0.4 (the
// cube packing of issue 3), dt = t_c / 25 of a cube-cube contact.
Material scene_material(const Shape& shape) {
  const double m = shape.table.type[0].mass, k = tol::contact_kind_scene_stiffness;
  return {Law{LinearSpringDashpot<double>::from_restitution(k, 0.3), HistoryFreeFriction<double>::make(0.4, 0.1)},
          kPi * std::sqrt(0.5 * m / k) / 25};
}

// A drum (thesis section 3.4.1): a horizontal cylinder (axis z, radius R) closed by two planar
// end plates; cubes at random orientations on a square grid of pitch 2.1 bounding radii (the
// packing's lattice) filling the disc, `layers` deep, all with velocity v0.
Packing<double> drum_scene(const PolyhedronTable<double>& table, double radius, int layers, const Vec3<double>& v0,
                           unsigned seed, double dt) {
  const double rb = table.type[0].bounding_radius, pitch = 2.1 * rb, length = layers * pitch;
  std::mt19937_64 rng(seed);
  Packing<double> p;
  const int m = static_cast<int>(radius / pitch) + 1;
  for (int k = 0; k < layers; ++k)
    for (int j = -m; j <= m; ++j)
      for (int i = -m; i <= m; ++i) {
        const Vec3<double> x{i * pitch, j * pitch, (k + 0.5) * pitch};
        if (std::hypot(x.x, x.y) > radius - 0.5 * pitch) continue;  // bounding sphere clear of the wall
        add_polyhedron(p.particles, table, 0, x, random_orientation(rng), 0, v0);
      }
  using V = Vec3<double>;
  const double r = radius;
  p.world.cylinders = {Cylinder<double>::make({0, 0, 0}, {0, 0, 1}, radius, length, 1)};
  p.world.polygons = {PlanarPolygon<double>::make({V{-r, -r, 0}, {r, -r, 0}, {r, r, 0}, {-r, r, 0}}, 1),
                      PlanarPolygon<double>::make({V{-r, r, length}, {r, r, length}, {r, -r, length}, {-r, -r, length}}, 1)};
  p.params = {dt, {0, -9.81, 0}, {-r - 4 * rb, -r - 4 * rb, -4 * rb}, {r + 4 * rb, r + 4 * rb, length + 4 * rb}, 0.2 * rb};
  return p;
}

// Translational plus rotational kinetic energy (J); the principal moments act on the body-frame
// angular velocity, w_body = q* w q.
double kinetic_energy(const ParticleState<double>& s) {
  double e = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const Quat<double>& q = s.orientation[i];
    const Vec3<double> w = rotate(Quat<double>{q.w, -q.x, -q.y, -q.z}, s.angular_velocity[i]);
    const Vec3<double>& in = s.inertia[i];
    e += 0.5 * s.mass[i] * norm2(s.velocity[i]) + 0.5 * (in.x * w.x * w.x + in.y * w.y * w.y + in.z * w.z * w.z);
  }
  return e;
}

// A state sampled for the thesis's rule (every tol::contact_kind_thesis_rule_every steps).
struct Sample {
  double t = 0;        // s
  HostKinds host;      // particle-particle contacts of the state, both classifications
  double kinetic = 0;  // J
};

struct KindRun {
  long particles = 0, removed = 0;
  long settled_steps = 0;             // steps with >= n/2 contacts ("once contacts exist")
  long settled_vf = 0, settled_ee = 0;  // summed over those steps
  long fewest_settled_contacts = 0;
  double max_fraction = 0;            // largest per-step fraction over those steps
  double final_fraction = 0;
  long final_contacts = 0, final_edge_edge = 0;
  double final_thesis_rule = 0;  // last step's fraction by the thesis's rule (host)
  std::vector<Sample> samples;
  double mean_fraction() const { return static_cast<double>(settled_ee) / static_cast<double>(settled_vf + settled_ee); }
};

// Runs a scene, recording the edge-edge fraction of every step (and, if `sample`, the host's
// classification of every tol::contact_kind_thesis_rule_every-th state), and checks the last
// step's counts against the host classification.
KindRun run_scene(const std::string& case_name, const Shape& shape, const ConvexShape& cube, const Law& law,
                  const Packing<double>& scene, double duration, bool sample, FigureData& fig) {
  Sim sim(scene.params, one_law(law), scene.world, scene.particles, shape);
  const long steps = std::lround(duration / static_cast<double>(scene.params.dt));
  KindRun run;
  run.particles = static_cast<long>(sim.size());
  run.fewest_settled_contacts = std::numeric_limits<long>::max();
  fig.block(case_name);
  std::pair<long, long> counts{0, 0};
  for (long s = 1; s <= steps; ++s) {
    sim.step();
    counts = sim.contact_counts();
    const long contacts = counts.first + counts.second;
    const double fraction = contacts > 0 ? static_cast<double>(counts.second) / static_cast<double>(contacts) : 0.0;
    fig.row(sim.time(), fraction, contacts, counts.first, counts.second);
    if (2 * contacts >= run.particles) {
      ++run.settled_steps;
      run.settled_vf += counts.first;
      run.settled_ee += counts.second;
      run.max_fraction = std::max(run.max_fraction, fraction);
      run.fewest_settled_contacts = std::min(run.fewest_settled_contacts, contacts);
    }
    if (sample && s % tol::contact_kind_thesis_rule_every == 0) {
      const ParticleState<double> state = sim.state();
      run.samples.push_back({static_cast<double>(sim.time()), classify_state(state, cube), kinetic_energy(state)});
    }
    run.final_fraction = fraction;
    run.final_contacts = contacts;
    run.final_edge_edge = counts.second;
  }
  run.removed = static_cast<long>(sim.removed_count());
  BOOST_TEST_MESSAGE(case_name << ": " << run.particles << " cubes, " << steps << " steps of " << scene.params.dt << " s; "
                               << run.settled_steps << " steps with >= n/2 contacts, edge-edge fraction mean "
                               << run.mean_fraction() << ", max " << run.max_fraction << "; final " << run.final_fraction
                               << " of " << run.final_contacts << " contacts");
  const HostKinds host = classify_state(sim.state(), cube);
  check_against_host(case_name, counts, host);
  run.final_thesis_rule = host.thesis_share();
  return run;
}

// Rows of one scenario, separating-axis kind: the fraction (mean over the steps with contacts,
// their maximum, the last step) against the random-contact value; then the thesis's rule on the
// last step's contacts.
void check_fractions(const std::string& case_name, const KindRun& run, double p_random, const std::string& thesis_max,
                     const std::string& thesis_final, double duration) {
  const std::string source = "random-contact value 9 pi / (24 + 9 pi) (integral geometry), band tol::contact_kind_band";
  const std::string over = " over steps with >= n/2 particle contacts, " + seconds(duration) + " run";
  BOOST_TEST(run.removed == 0);
  BOOST_REQUIRE(run.settled_steps > 0);
  check_at_least({case_name, kSat + "edge-edge contacts at the last step (they occur)", "> 0", "thesis Fig 3.27"},
                 static_cast<double>(run.final_edge_edge), 1);
  check_near({case_name, kSat + "edge-edge fraction, mean" + over, thesis_max, source}, run.mean_fraction(), p_random,
             tol::contact_kind_band);
  // Per-step fractions scatter like a binomial proportion of the step's contact count.
  const auto noise = [&](long contacts) {
    return tol::contact_kind_sigmas * std::sqrt(p_random * (1 - p_random) / static_cast<double>(contacts));
  };
  check_at_most({case_name, kSat + "edge-edge fraction, max" + over, thesis_max, source}, run.max_fraction,
                p_random + tol::contact_kind_band + noise(run.fewest_settled_contacts));
  check_near({case_name, kSat + "edge-edge fraction at the last step", thesis_final, source}, run.final_fraction, p_random,
             tol::contact_kind_band + noise(run.final_contacts));
  // The thesis's rule calls a contact Type 1 as soon as a vertex of either cube is inside the
  // other; most of the separating-axis edge-edge contacts of a bed hold such a vertex.
  check_at_most({case_name, kRule + "edge-edge share at the last step", thesis_final,
                 "host vertex containment; bound: the SAT-kind share of the same contacts"},
                run.final_thesis_rule, run.final_fraction);
}

// Scenario (a) by the thesis's rule once the bed has settled, pooled over beds that differ only
// in their random orientations (tol::contact_kind_settled_seeds of them). The packing is chaotic:
// a last-bit change anywhere (the orientation step's rounding, say) sends one bed down another
// trajectory, whose settled share lies anywhere in the seeds' spread (0.097-0.151 measured), so
// one trajectory is not a measurement of the share. The settled phase is the last
// tol::contact_kind_settled_window of each run (samples every tol::contact_kind_thesis_rule_every
// steps); a bed counts as settled when the phase's mean kinetic energy is a small share of its
// run's peak. The share there (edge-edge over all contacts of all beds' phase samples) is the
// issue's assertion; the share while the beds collapse (samples of the first third of each run
// with >= n/2 contacts) shows it fall. A single bed (CI) cannot resolve the bound and is
// held to a one-bed bound (tolerances.hpp).
void check_settled_share(const std::string& case_name, const std::vector<KindRun>& runs, double duration, FigureData& fig) {
  const bool pooled = runs.size() >= static_cast<std::size_t>(tol::contact_kind_settled_seeds);
  const double bound = pooled ? tol::contact_kind_settled_share : tol::contact_kind_settled_share_one_bed;
  const std::string bound_source = pooled ? "issue 4: below 15%; thesis Fig 3.27a"
                                          : "one bed: tol::contact_kind_settled_share_one_bed; make stress pools " +
                                                std::to_string(tol::contact_kind_settled_seeds) + " against 15%";
  const double start = (1 - tol::contact_kind_settled_window) * duration;
  HostKinds settled, collapsing;
  double lowest = 1, highest = 0, worst_kinetic = 0;
  long n_settled = 0;
  std::string per_bed, course;
  for (const KindRun& run : runs) {
    HostKinds bed;
    double peak = 0, kinetic = 0;
    long n_bed = 0;
    for (const Sample& x : run.samples) peak = std::max(peak, x.kinetic);
    for (const Sample& x : run.samples) {
      if (x.t > start) bed += x.host, kinetic += x.kinetic, ++n_bed;
      if (x.t <= duration / 3 && 2 * (x.host.thesis_vertex_face + x.host.thesis_edge_edge) >= run.particles)
        collapsing += x.host;
    }
    BOOST_REQUIRE(n_bed > 0);
    worst_kinetic = std::max(worst_kinetic, kinetic / static_cast<double>(n_bed) / peak);
    settled += bed, n_settled += n_bed;
    lowest = std::min(lowest, bed.thesis_share()), highest = std::max(highest, bed.thesis_share());
    per_bed += " " + std::to_string(bed.thesis_share()).substr(0, 5);
  }
  // The share's course over the first bed, in tenths of the run (for the report and the figure).
  for (int k = 1; k <= 10; ++k) {
    HostKinds bin;
    for (const Sample& x : runs.front().samples)
      if (x.t > (k - 1) * duration / 10 && x.t <= k * duration / 10) bin += x.host;
    course += " " + std::to_string(bin.thesis_share()).substr(0, 5);
  }
  BOOST_TEST_MESSAGE(case_name << ": thesis-rule edge-edge share per tenth of the first bed's run:" << course
                               << "; settled phase (t > " << start << " s, " << n_settled << " samples of " << runs.size()
                               << " beds): " << settled.thesis_share() << " (beds:" << per_bed
                               << "), largest mean kinetic energy " << worst_kinetic << " of its run's peak");
  fig.block("settled phase of (a), all beds: t_start_s t_end_s thesis_rule_share bound lowest_bed highest_bed");
  fig.row(start, duration, settled.thesis_share(), bound, lowest, highest);
  const std::string phase = "last " + std::to_string(static_cast<int>(100 * tol::contact_kind_settled_window)) + "% of a " +
                            seconds(duration) + " run, every " + std::to_string(tol::contact_kind_thesis_rule_every) +
                            " steps, " + std::to_string(runs.size()) + " beds";
  check_at_most({case_name, "beds settled: largest mean kinetic energy over the " + phase + " / its run's peak", "-",
                 "tol::contact_kind_settled_kinetic"},
                worst_kinetic, tol::contact_kind_settled_kinetic);
  check_at_most({case_name, kRule + "edge-edge share over the settled phase (" + phase + ")", "<= 10%", bound_source},
                settled.thesis_share(), bound);
  check_at_least({case_name, kRule + "edge-edge share while the beds collapse (first third, >= n/2 contacts), above the settled share",
                  "-", "thesis 3.4.3: edge-edge share falls as the bed settles"},
                 collapsing.thesis_share(), settled.thesis_share());
}

}  // namespace

BOOST_AUTO_TEST_SUITE(contact_types)

// Random cube pairs brought into first touch along random lines: the kernel's edge-edge share is
// the Minkowski-difference area fraction P_ee. Each pair: random orientations, a direction u and
// an impact point uniform in the disc of radius `reach` across u; B comes in along -u until it
// first touches A (scan, then bisection on the kernel's own touching test, whose correctness the
// issue-3 reference test covers), then goes 1e-6 reach deeper. All pairs are one simulation; its
// first force evaluation gives the counts.
BOOST_AUTO_TEST_CASE(first_touch_kind_follows_integral_geometry) {
  const ConvexShape cube = load_shape(kCubeFile);
  Shape shape;
  shape.table.add(cube, kDensity);
  const double s = surface_area(cube), m = mean_curvature_integral(cube), edge = std::cbrt(cube.volume);
  const double p_random = random_contact_edge_edge(s, m);
  check_relative({"Contact kind of random first touches (integral geometry)", "cube: S / a^2 from the shape file", "-",
                  "S = 6 a^2"},
                 s / (edge * edge), 6.0, tol::geometry_double);
  check_relative({"Contact kind of random first touches (integral geometry)", "cube: M / a from the shape file", "-",
                  "M = 3 pi a"},
                 m / edge, 3 * kPi, tol::geometry_double);

  const long n = tol::contact_kind_first_touch_pairs;
  const double reach = 2 * cube.bounding_radius, spacing = 3 * reach;
  const int side = lattice_side(n);
  std::mt19937_64 rng(27);
  std::uniform_real_distribution<double> uniform(0, 1);
  ParticleState<double> pairs;
  HostKinds host;
  long misses = 0;
  for (long k = 0; k < n;) {
    const Quat<double> qa = random_orientation(rng), qb = random_orientation(rng);
    const Vec3<double> u = random_direction(rng);
    // Two unit vectors across u, and the impact point b in the disc of radius reach.
    Vec3<double> e1 = cross(u, std::fabs(u.x) < 0.9 ? Vec3<double>{1, 0, 0} : Vec3<double>{0, 1, 0});
    e1 *= 1.0 / norm(e1);
    const Vec3<double> e2 = cross(u, e1);
    const double rho = reach * std::sqrt(uniform(rng)), phi = 2 * kPi * uniform(rng);
    const Vec3<double> b = e1 * (rho * std::cos(phi)) + e2 * (rho * std::sin(phi));
    const auto touching = [&](double t) {
      return shape.collide(Shape::Body{{0, 0, 0}, qa, 0, 0}, Shape::Body{b + u * t, qb, 0, 1}).touching;
    };
    const int scan = static_cast<int>(tol::contact_kind_scan_points);
    double lo = reach, hi = reach;  // lo: apart, hi: touching
    bool hit = false;
    for (int i = 1; i <= scan && !hit; ++i) {
      const double t = reach - 2 * reach * i / scan;
      if (touching(t)) hit = true, hi = t;
      else lo = t;
    }
    if (!hit) {
      ++misses;
      continue;
    }
    for (int it = 0; it < 60; ++it) (touching(0.5 * (lo + hi)) ? hi : lo) = 0.5 * (lo + hi);
    const Vec3<double> rel = b + u * (hi - 1e-6 * reach);
    const Vec3<double> centre{(k % side) * spacing, ((k / side) % side) * spacing, (k / (side * side)) * spacing};
    add_polyhedron(pairs, shape.table, 0, centre, qa, 0);
    add_polyhedron(pairs, shape.table, 0, centre + rel, qb, 0);
    host += classify(place(cube, centre, qa), place(cube, centre + rel, qb), reach);
    ++k;
  }
  const double extent = side * spacing + spacing;
  const SimulationParams<double> prm{1e-6, {0, 0, 0}, {-spacing, -spacing, -spacing}, {extent, extent, extent}, 0.05 * reach};
  const Material mat = scene_material(shape);
  Sim sim(prm, one_law(mat.law), World<double>{}, pairs, shape);
  const auto [vertex_face, edge_edge] = sim.contact_counts();
  const double fraction = static_cast<double>(edge_edge) / static_cast<double>(vertex_face + edge_edge);
  BOOST_TEST_MESSAGE("first touches: " << n << " pairs (" << misses << " lines missed), " << edge_edge
                                       << " edge-edge: fraction " << fraction << ", integral geometry " << p_random
                                       << "; thesis rule " << host.thesis_share());
  const std::string case_name = "Contact kind of random first touches (integral geometry)";
  // Cauchy: the mean shadow of a convex body is S/4, so a line of the disc hits A - B with
  // probability E[S] / (4 pi reach^2), E[S] = 2 S + M^2 / (2 pi).
  const double hit_share = static_cast<double>(n) / static_cast<double>(n + misses);
  check_near({case_name, "share of random lines that hit A - B", "-", "E[S] / (4 pi reach^2), E[S] = 2 S + M^2 / (2 pi)"},
             hit_share, (2 * s + m * m / (2 * kPi)) / (4 * kPi * reach * reach), tol::contact_kind_first_touch);
  check_near({case_name, "touching pairs found by the kernel", "-", "every pair placed 1e-6 reach past first touch"},
             static_cast<double>(vertex_face + edge_edge), static_cast<double>(n), 0);
  check_against_host(case_name, {vertex_face, edge_edge}, host);
  check_near({case_name, kSat + "edge-edge fraction of " + std::to_string(n) + " random cube pairs", "-",
              "P_ee = 9 pi / (24 + 9 pi) = 0.5409 (rotation mean of mixed area)"},
             fraction, p_random, tol::contact_kind_first_touch);
}

// Fig 3.27: the edge-edge fraction per step in (a) a gravity packing in a box, (b) a gravity
// packing in a drum from rest, (c) the same drum with every cube moving at 1 m/s towards the
// right-hand wall (+x), so the whole load strikes the drum (the thesis's 0.2 cm/s of section 3.4.1
// would not reach it before gravity does).
BOOST_AUTO_TEST_CASE(fig_3_27_edge_edge_fraction) {
  const ConvexShape cube = load_shape(kCubeFile);
  Shape shape;
  shape.table.add(cube, kDensity);
  const double p_random = random_contact_edge_edge(surface_area(cube), mean_curvature_integral(cube));
  const Material mat = scene_material(shape);
  FigureData fig("fig-3.27", "t_s edge_edge_fraction contacts vertex_face edge_edge");
  // The box runs until its bed has settled, the drums for the first 0.2 s (their share is
  // near the random value throughout). The figure shows runs twice as long.
  const double stretch = fig.enabled() ? 2 : 1;
  const double box_duration = stretch * tol::contact_kind_box_duration, drum_duration = stretch * tol::contact_kind_duration;
  const double radius = tol::contact_kind_drum_radius_edges * std::cbrt(cube.volume);
  const int layers = static_cast<int>(tol::contact_kind_drum_layers);

  const std::string name_a = "Contact kinds (a): packing in a box (3.4.3, Fig 3.27a)";
  const std::string name_b = "Contact kinds (b): drum from rest (3.4.3, Fig 3.27b)";
  const std::string name_c = "Contact kinds (c): drum, 1 m/s to the wall (3.4.3, Fig 3.27c)";
  // Bed (a) with seed 3 is the figure's and the fraction checks'; seeds 4, 5, ... join it for the
  // settled share under `make stress` and for the figure. CI runs seed 3 alone, which does not
  // resolve the bound: it is held to a one-bed bound (tolerances.hpp).
  const bool all_beds = full_size() || fig.enabled();
  const long n_beds = all_beds ? tol::contact_kind_settled_seeds : tol::contact_kind_settled_seeds_ci;
  std::vector<KindRun> beds;
  for (unsigned seed = 3; beds.size() < static_cast<std::size_t>(n_beds); ++seed) {
    const auto box = polyhedron_packing(shape.table, 0, static_cast<int>(tol::contact_kind_box_cubes), seed, mat.dt);
    FigureData quiet;  // only the first bed's steps go to the figure
    beds.push_back(run_scene(beds.empty() ? name_a : name_a + ", seed " + std::to_string(seed), shape, cube, mat.law, box, box_duration, true,
                             beds.empty() ? fig : quiet));
  }
  const KindRun& a = beds.front();
  const auto drum_rest = drum_scene(shape.table, radius, layers, {0, 0, 0}, 4, mat.dt);
  const KindRun b = run_scene(name_b, shape, cube, mat.law, drum_rest, drum_duration, fig.enabled(), fig);
  const auto drum_moving = drum_scene(shape.table, radius, layers, {1, 0, 0}, 4, mat.dt);
  const KindRun c = run_scene(name_c, shape, cube, mat.law, drum_moving, drum_duration, fig.enabled(), fig);

  // The same contacts by the thesis's rule (Type 1 whenever a vertex of either cube is inside
  // the other), sampled on the host (the drums only for the figure).
  for (const KindRun* run : {&a, &b, &c}) {
    double peak = 0;
    for (const Sample& x : run->samples) peak = std::max(peak, x.kinetic);
    fig.block("thesis rule, sampled: t_s edge_edge_fraction contacts kinetic_over_peak");
    for (const Sample& x : run->samples)
      fig.row(x.t, x.host.thesis_share(), x.host.thesis_vertex_face + x.host.thesis_edge_edge, x.kinetic / peak);
  }

  check_fractions(name_a, a, p_random, "-", "-", box_duration);
  check_settled_share(name_a, beds, box_duration, fig);
  check_fractions(name_b, b, p_random, "slightly > (a)", "-", drum_duration);
  check_fractions(name_c, c, p_random, "up to 30%", "falls to (a)'s", drum_duration);
}

BOOST_AUTO_TEST_SUITE_END()
