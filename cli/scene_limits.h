#pragma once
// The range each number of a scene file (and the options that override it)
// must lie in. Every bound is far beyond a real set-up and keeps the products
// the simulation forms (mass, stiffness * dt^2, kinetic energy, pixel counts)
// well inside double range, so a hostile value is refused while parsing
// instead of turning into NaN or an allocation that cannot succeed.
#include <string>

namespace recoil::cli {

struct Range {
  double lo = 0.0;
  double hi = 0.0;
  bool open_lo = false;  // lo itself is excluded
  bool open_hi = false;

  bool contains(double x) const { return (open_lo ? x > lo : x >= lo) && (open_hi ? x < hi : x <= hi); }
  // "in [1e-06, 1]" or "> 0", for messages.
  std::string describe() const;
};

inline constexpr Range kCoordinateRange{-1e5, 1e5};        // m: positions, targets, pin boxes, plane points
inline constexpr Range kSizeRange{1e-6, 1e5};               // m: box edges, radii, heights, collision edges
inline constexpr Range kScaleRange{1e-9, 1e9};              // |scale factor|, nanometre units and back; negative mirrors
inline constexpr Range kSpeedRange{-1e4, 1e4};              // m/s, each component of a velocity
inline constexpr Range kAngularSpeedRange{-1e4, 1e4};       // rad/s, each component
inline constexpr Range kAngleRange{-1e5, 1e5};              // degrees: rotations, azimuths
inline constexpr Range kAccelerationRange{-1e4, 1e4};       // m/s^2, each component of gravity
inline constexpr Range kDensityRange{1e-3, 1e5};            // kg/m^3 (aerogel to well past osmium)
inline constexpr Range kYoungsModulusRange{1.0, 1e13};      // Pa (soft gel to past diamond)
inline constexpr Range kTimeStepRange{1e-6, 1.0};           // s
inline constexpr Range kDurationRange{0.0, 1e6};            // s of simulated time
inline constexpr Range kFpsRange{1e-3, 1000.0};             // frames per second
inline constexpr Range kToleranceRange{1e-12, 1.0};         // m/s, the solver's KKT tolerance
inline constexpr Range kMarginRange{1e-6, 1.0};             // m, the contact margin
inline constexpr Range kFrictionRange{0.0, 10.0};           // Coulomb coefficients
inline constexpr Range kCameraDistanceRange{1e-3, 1e5};     // m from the target
inline constexpr Range kTurnsRange{-1e4, 1e4};              // orbit turns over the run

// A collision surface's triangle budget ({"triangles": N}, --collision-triangles):
// at least a tetrahedron's four faces.
inline constexpr int kMinCollisionTriangles = 4, kMaxCollisionTriangles = 100'000'000;

inline constexpr long kMaxSteps = 100'000'000;   // duration / dt: days of work on the smallest scene
inline constexpr int kMaxFrames = 1'000'000;     // duration * fps + 1
inline constexpr int kMaxIterations = 1'000'000; // the solver's cap per step
inline constexpr int kMaxBodies = 10'000;      // ten times drop's largest pile; each body's mesh is parsed up front
inline constexpr unsigned long kMaxSceneBytes = 32ul << 20;  // a scene file's size; kMaxBodies bodies take ~2 MiB
inline constexpr int kMaxNameBytes = 128;        // a scene or body name (a folder name, well under NAME_MAX)

// Why `name` cannot be a scene or body name ("" when it can): it must be a
// usable folder name, so not empty, ".", ".." or longer than kMaxNameBytes,
// and free of '/' and control characters.
std::string unsafe_name_reason(const std::string& name);

// A scene or body name taken from a mesh file's stem by the commands that
// build scenes (drop, turntable): cut, at a character boundary, to leave
// room for a suffix of up to kNameSuffixBytes ("-pile", "-1000"), control
// characters replaced by '_'; "mesh" for nothing left.
inline constexpr int kNameSuffixBytes = 8;
std::string name_from_stem(const std::string& stem);

}  // namespace recoil::cli
