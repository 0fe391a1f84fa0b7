// The scaling benchmark's Embree side: the same workload as `examples/scale` (the spec's
// camera, matte albedo 0.5 everywhere, the default sky, no lights, max depth 10), traced with
// Embree 3's rtcIntersect1 one ray at a time, on a scene exported by
// `cargo run --release --example scale -- --scene ... --export FILE`.
//
// It prints the build time (rtcCommitScene alone), Mrays/s of the render, rays traced and
// the peak memory (VmHWM) in the Rust program's format; with --csv one CSV line on stdout
// (scene,primitives,program,threads,build_s,mrays_s,rays,peak_mb), the summary on stderr.
//
// Spawned rays start at the hit point with tnear = 1e-5 * (largest coordinate magnitude of
// the scene's bounds, at least 1): about 80 float ulps of the scene's coordinates, enough
// to step off the surface just hit, far below the smallest primitive (a sphere of radius
// 0.02 at a million spheres, triangles ~0.01 across in the full dragon).
//
// Build: bench/embree/build.sh.  Usage: scale --scene FILE [--name NAME] [--threads N]
//   [--spp N] [--width W] [--max-depth D] [--seed S] [--quality medium|high] [--csv]
//   [--image FILE.ppm]

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

struct Options {
  std::string scene, name, quality = "medium", image;
  unsigned threads = 1, spp = 8, width = 400, max_depth = 10;
  uint64_t seed = 0;
  bool csv = false;
};

// The exported scene (format documented in examples/scale/export.rs).
struct SceneData {
  bool spheres = false;
  std::vector<float> floats;     // x y z r per sphere, or x y z per vertex
  std::vector<uint32_t> indices; // a b c per triangle
  size_t primitives = 0;
};

[[noreturn]] void fail(const std::string& message) {
  std::fprintf(stderr, "error: %s\n", message.c_str());
  std::exit(1);
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) fail("missing value after " + a);
      return argv[++i];
    };
    auto number = [&]() -> unsigned long {
      std::string v = value();
      char* end = nullptr;
      unsigned long n = std::strtoul(v.c_str(), &end, 10);
      if (v.empty() || *end != '\0') fail("expected a whole number after " + a + ", got " + v);
      return n;
    };
    if (a == "--scene") o.scene = value();
    else if (a == "--name") o.name = value();
    else if (a == "--threads") o.threads = number();
    else if (a == "--spp") o.spp = number();
    else if (a == "--width") o.width = number();
    else if (a == "--max-depth") o.max_depth = number();
    else if (a == "--seed") o.seed = number();
    else if (a == "--quality") o.quality = value();
    else if (a == "--image") o.image = value();
    else if (a == "--csv") o.csv = true;
    else fail("unknown option " + a);
  }
  if (o.scene.empty()) fail("--scene FILE is required");
  if (o.quality != "medium" && o.quality != "high") fail("--quality must be medium or high");
  if (o.threads < 1 || o.spp < 1 || o.width < 4 || o.width % 2 != 0)
    fail("need --threads >= 1, --spp >= 1 and an even --width >= 4");
  if (o.name.empty()) {
    std::string stem = o.scene.substr(o.scene.find_last_of('/') + 1);
    o.name = stem.substr(0, stem.find_last_of('.'));
  }
  return o;
}

template <typename T> T take(std::ifstream& in) {
  T v;
  if (!in.read(reinterpret_cast<char*>(&v), sizeof v)) fail("the scene file is truncated");
  return v;
}

template <typename T> void take_many(std::ifstream& in, std::vector<T>& out, size_t n) {
  out.resize(n);
  if (!in.read(reinterpret_cast<char*>(out.data()), n * sizeof(T))) fail("the scene file is truncated");
}

SceneData load(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail("cannot open " + path);
  char magic[8];
  if (!in.read(magic, 8) || std::memcmp(magic, "RTSCALE1", 8) != 0) fail(path + " is not a scale scene file");
  uint32_t kind = take<uint32_t>(in);
  take<uint32_t>(in);
  SceneData s;
  if (kind == 1) {
    s.spheres = true;
    s.primitives = take<uint64_t>(in);
    take_many(in, s.floats, 4 * s.primitives);
  } else if (kind == 2) {
    uint64_t vertices = take<uint64_t>(in);
    s.primitives = take<uint64_t>(in);
    take_many(in, s.floats, 3 * vertices);
    take_many(in, s.indices, 3 * s.primitives);
    for (uint32_t i : s.indices)
      if (i >= vertices) fail("a triangle indexes past the vertices");
  } else {
    fail("unknown scene kind in " + path);
  }
  return s;
}

// A buffer with 16 bytes of slack: Embree may read a vertex with one 16-byte load.
void set_buffer(RTCDevice device, RTCGeometry g, RTCBufferType type, RTCFormat format, const void* data,
                size_t stride, size_t count) {
  size_t bytes = stride * count;
  RTCBuffer buffer = rtcNewBuffer(device, bytes + 16);
  std::memcpy(rtcGetBufferData(buffer), data, bytes);
  rtcSetGeometryBuffer(g, type, 0, format, buffer, 0, stride, count);
  rtcReleaseBuffer(buffer);
}

// Adds the geometry to a new scene (not yet committed) and returns the tnear epsilon.
float add_geometry(RTCDevice device, RTCScene scene, const SceneData& s, RTCBuildQuality quality) {
  RTCGeometry g;
  float extent = 1.0f;
  if (s.spheres) {
    g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
    set_buffer(device, g, RTC_BUFFER_TYPE_VERTEX, RTC_FORMAT_FLOAT4, s.floats.data(), 16, s.primitives);
    for (size_t i = 0; i < s.floats.size(); i += 4)
      for (int k = 0; k < 3; ++k) extent = std::max(extent, std::fabs(s.floats[i + k]) + s.floats[i + 3]);
  } else {
    g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    set_buffer(device, g, RTC_BUFFER_TYPE_VERTEX, RTC_FORMAT_FLOAT3, s.floats.data(), 12, s.floats.size() / 3);
    set_buffer(device, g, RTC_BUFFER_TYPE_INDEX, RTC_FORMAT_UINT3, s.indices.data(), 12, s.primitives);
    for (float c : s.floats) extent = std::max(extent, std::fabs(c));
  }
  rtcSetGeometryBuildQuality(g, quality);
  rtcCommitGeometry(g);
  rtcAttachGeometry(scene, g);
  rtcReleaseGeometry(g);
  return 1e-5f * extent;
}

// One SplitMix64 output for state x: seeds and steps each sample's generator.
uint64_t mix64(uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// A sample's own generator (a SplitMix64 stream), seeded from (seed, pixel, sample).
struct Rng {
  uint64_t state;
  Rng(uint64_t seed, uint64_t pixel, uint64_t sample)
      : state(mix64(mix64(mix64(seed) ^ pixel * 0x9E3779B97F4A7C15ull) ^ sample)) {}
  double uniform() { // [0, 1) from 53 bits
    state += 0x9E3779B97F4A7C15ull;
    return double(mix64(state) >> 11) * 0x1.0p-53;
  }
};

struct V3 {
  float x, y, z;
};
V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 operator*(V3 a, float s) { return {a.x * s, a.y * s, a.z * s}; }
float dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// The library's matte scatter: a point uniform on the unit sphere (cube rejection) added to
// the normal and normalised, density cos(theta)/pi about n.
V3 lambertian(V3 n, Rng& rng) {
  for (;;) {
    double x = 2 * rng.uniform() - 1, y = 2 * rng.uniform() - 1, z = 2 * rng.uniform() - 1;
    double len2 = x * x + y * y + z * z;
    if (len2 > 1.0 || len2 <= 1e-12) continue;
    double inv = 1.0 / std::sqrt(len2);
    V3 d = n + V3{float(x * inv), float(y * inv), float(z * inv)};
    float dd = dot(d, d);
    if (dd > 64 * 1.1920929e-7f) return d * (1.0f / std::sqrt(dd));
  }
}

// The default sky: white at y = -1 blending to (0.5, 0.7, 1) at y = +1.
V3 sky(V3 d) {
  float s = (d.y + 1) * 0.5f;
  return V3{1, 1, 1} * (1 - s) + V3{0.5f, 0.7f, 1.0f} * s;
}

struct Render {
  std::vector<V3> image;
  uint64_t rays = 0;
  double seconds = 0;
};

// One path from the camera: every surface absorbs half; black after max_depth bounces.
V3 trace(RTCScene scene, V3 org, V3 dir, const Options& o, float eps, Rng& rng, uint64_t& rays) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  float throughput = 1;
  float tnear = 0;
  for (unsigned depth = 0;; ++depth) {
    RTCRayHit rh;
    rh.ray.org_x = org.x, rh.ray.org_y = org.y, rh.ray.org_z = org.z;
    rh.ray.dir_x = dir.x, rh.ray.dir_y = dir.y, rh.ray.dir_z = dir.z;
    rh.ray.tnear = tnear;
    rh.ray.tfar = INFINITY;
    rh.ray.time = 0, rh.ray.mask = ~0u, rh.ray.id = 0, rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    ++rays;
    rtcIntersect1(scene, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return sky(dir) * throughput;
    if (depth >= o.max_depth) return V3{0, 0, 0};
    V3 n{rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z};
    n = n * ((dot(n, dir) > 0 ? -1.0f : 1.0f) / std::sqrt(dot(n, n))); // face the ray
    org = org + dir * rh.ray.tfar;
    dir = lambertian(n, rng);
    throughput *= 0.5f;
    tnear = eps;
  }
}

// Rows handed out one at a time to the threads; each sample draws its own stream.
Render render(RTCScene scene, const Options& o, float eps) {
  unsigned w = o.width, h = o.width / 2;
  Render r;
  r.image.assign(size_t(w) * h, V3{0, 0, 0});
  std::atomic<unsigned> next_row{0};
  std::vector<uint64_t> rays(o.threads, 0);
  float sx = 4.0f / float(w - 1), sy = 2.0f / float(h - 1);
  auto work = [&](unsigned t) {
    for (unsigned y; (y = next_row.fetch_add(1)) < h;) {
      for (unsigned x = 0; x < w; ++x) {
        uint64_t pixel = uint64_t(y) * w + x;
        V3 sum{0, 0, 0};
        for (unsigned s = 0; s < o.spp; ++s) {
          Rng rng(o.seed, pixel, s);
          float px = float(x), py = float(y);
          if (o.spp > 1) { // uniform in the pixel's cell, as the library jitters
            px += float(rng.uniform() - 0.5);
            py += float(rng.uniform() - 0.5);
          }
          V3 p{-2.0f + px * sx, 1.0f - py * sy, -1.0f};
          V3 dir = p * (1.0f / std::sqrt(dot(p, p)));
          sum = sum + trace(scene, V3{0, 0, 0}, dir, o, eps, rng, rays[t]);
        }
        r.image[pixel] = sum * (1.0f / float(o.spp));
      }
    }
  };
  auto start = std::chrono::steady_clock::now();
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < o.threads; ++t) pool.emplace_back(work, t);
  work(0);
  for (auto& th : pool) th.join();
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (uint64_t n : rays) r.rays += n;
  return r;
}

// Peak resident memory in MB (10^6 bytes), from VmHWM.
double peak_mb() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) * 1024.0 / 1e6;
  return NAN;
}

void write_ppm(const std::string& path, const Render& r, unsigned w, unsigned h) {
  std::ofstream out(path, std::ios::binary);
  out << "P6\n" << w << " " << h << "\n255\n";
  auto srgb = [](float c) {
    c = std::clamp(c, 0.0f, 1.0f);
    c = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1 / 2.4f) - 0.055f;
    return char(std::lround(c * 255));
  };
  for (V3 c : r.image) out << srgb(c.x) << srgb(c.y) << srgb(c.z);
  if (!out) fail("cannot write " + path);
}

} // namespace

int main(int argc, char** argv) {
  Options o = parse(argc, argv);
  std::string config = "threads=" + std::to_string(o.threads);
  RTCDevice device = rtcNewDevice(config.c_str());
  if (!device) fail("cannot create the Embree device");
  rtcSetDeviceErrorFunction(
      device, [](void*, RTCError code, const char* text) { fail("Embree error " + std::to_string(code) + ": " + text); },
      nullptr);
  RTCBuildQuality quality = o.quality == "high" ? RTC_BUILD_QUALITY_HIGH : RTC_BUILD_QUALITY_MEDIUM;
  size_t primitives;
  float eps;
  RTCScene scene = rtcNewScene(device);
  rtcSetSceneBuildQuality(scene, quality);
  {
    SceneData data = load(o.scene); // freed once Embree holds its copy
    primitives = data.primitives;
    eps = add_geometry(device, scene, data, quality);
  }
  auto start = std::chrono::steady_clock::now();
  rtcCommitScene(scene);
  double build_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  Render r = render(scene, o, eps);
  double mrays = double(r.rays) / std::max(r.seconds, 1e-9) / 1e6;
  double peak = peak_mb();
  std::string program = "embree-" + o.quality;
  std::ostringstream summary;
  summary << o.name << ": " << primitives << " primitives, " << program << " on " << o.threads << " thread(s)\n";
  char line[256];
  std::snprintf(line, sizeof line, "  build:  %.6f s\n  render: %.3f s, %llu rays, %.3f Mrays/s\n  peak:   %.1f MB (VmHWM)",
                build_s, r.seconds, (unsigned long long)r.rays, mrays, peak);
  summary << line;
  if (o.csv) {
    std::fprintf(stderr, "%s\n", summary.str().c_str());
    std::printf("%s,%zu,%s,%u,%.6f,%.4f,%llu,%.1f\n", o.name.c_str(), primitives, program.c_str(), o.threads, build_s,
                mrays, (unsigned long long)r.rays, peak);
  } else {
    std::printf("%s\n", summary.str().c_str());
  }
  if (!o.image.empty()) write_ppm(o.image, r, o.width, o.width / 2);
  rtcReleaseScene(scene);
  rtcReleaseDevice(device);
  return 0;
}
