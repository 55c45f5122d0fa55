// Checkpoint round trip (bit for bit) and the errors for each kind of bad file.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "common/checkpoint.hpp"
#include "tests/temp_dir_test.hpp"

namespace impactsph {
namespace {

namespace fs = std::filesystem;

class CheckpointTest : public TempDirTest {
 protected:
  CheckpointTest() : TempDirTest("impactsph_checkpoint") {}
  static void spit(const fs::path& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << bytes;
  }
  // The message of read_checkpoint's error for `bytes`, or "<no exception>".
  std::string read_error(const std::string& bytes) {
    const fs::path file = dir_ / "bad.ckpt";
    spit(file, bytes);
    try {
      read_checkpoint(file);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "<no exception>";
  }

};

// Values that only a raw copy preserves: NaN payloads, signed zero, subnormals.
ParticleSet awkward_particles(std::size_t n) {
  ParticleSet p;
  p.resize(n);
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    p.pos[i] = {u(rng), u(rng), u(rng)};
    p.vel[i] = {u(rng) * 1e3, -0.0, std::numeric_limits<double>::denorm_min()};
    p.mass[i] = 1e-6 * (1 + u(rng));
    p.rho[i] = 7850 * (1 + 1e-3 * u(rng));
    std::uint64_t nan_bits = 0x7ff8dead00000000ull + i;
    std::memcpy(&p.energy[i], &nan_bits, sizeof nan_bits);
    p.pressure[i] = u(rng) * 1e9;
    p.h[i] = 1e-4 + 1e-6 * u(rng);
    p.dev_stress[i] = {u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)};
    p.plastic_strain[i] = std::abs(u(rng));
    p.plastic_work[i] = 1e6 * std::abs(u(rng));
    p.damage[i] = std::abs(u(rng));
    p.body[i] = static_cast<std::int32_t>(i % 3);
    p.material[i] = static_cast<std::int32_t>(i % 2);
    p.fixed[i] = static_cast<std::uint8_t>(i % 5 == 0);
    p.acceleration[i] = {1e9 * u(rng), u(rng) / 7, -u(rng)};
    p.energy_rate[i] = 1e11 * u(rng);
    p.density_diffusion[i] = 1e6 * u(rng);
    p.contact_power[i] = u(rng) / 3;
  }
  p.rates_current = true;
  return p;
}

RunClock sample_clock() {
  RunClock c;
  c.time = 1.0 / 3.0 * 1e-5;
  c.step = 12345;
  c.frame = 7;
  c.next_output = 3.5e-6;
  c.next_frame = 4e-6;
  c.next_checkpoint = 1e-5;
  c.wall_seconds = 12.75;
  c.neighbour_sum = 6.1e5;
  return c;
}

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

TEST_F(CheckpointTest, RoundTripIsBitExact) {
  const ParticleSet p = awkward_particles(37);
  const RunClock clock = sample_clock();
  using namespace std::string_literals;
  const std::string fingerprint = "case=taylor.toml sha=abc\n\0binary-safe"s;
  const fs::path file = dir_ / "run.ckpt";
  write_checkpoint(file, p, clock, fingerprint);
  const CheckpointData d = read_checkpoint(file);

  EXPECT_TRUE(same_bits(d.particles.pos, p.pos));
  EXPECT_TRUE(same_bits(d.particles.vel, p.vel));
  EXPECT_TRUE(same_bits(d.particles.mass, p.mass));
  EXPECT_TRUE(same_bits(d.particles.rho, p.rho));
  EXPECT_TRUE(same_bits(d.particles.energy, p.energy));
  EXPECT_TRUE(same_bits(d.particles.pressure, p.pressure));
  EXPECT_TRUE(same_bits(d.particles.h, p.h));
  EXPECT_TRUE(same_bits(d.particles.dev_stress, p.dev_stress));
  EXPECT_TRUE(same_bits(d.particles.plastic_strain, p.plastic_strain));
  EXPECT_TRUE(same_bits(d.particles.plastic_work, p.plastic_work));
  EXPECT_TRUE(same_bits(d.particles.damage, p.damage));
  EXPECT_TRUE(same_bits(d.particles.body, p.body));
  EXPECT_TRUE(same_bits(d.particles.material, p.material));
  EXPECT_TRUE(same_bits(d.particles.fixed, p.fixed));
  EXPECT_TRUE(same_bits(d.particles.acceleration, p.acceleration));
  EXPECT_TRUE(same_bits(d.particles.energy_rate, p.energy_rate));
  EXPECT_TRUE(same_bits(d.particles.density_diffusion, p.density_diffusion));
  EXPECT_TRUE(same_bits(d.particles.contact_power, p.contact_power));
  EXPECT_TRUE(d.particles.rates_current);
  EXPECT_EQ(std::memcmp(&d.clock, &clock, sizeof clock), 0);
  EXPECT_EQ(d.fingerprint, fingerprint);

  // Writing the read state again gives the same file: nothing is lost or reordered.
  const std::string first = slurp(file);
  write_checkpoint(file, d.particles, d.clock, d.fingerprint);
  EXPECT_EQ(slurp(file), first);
  for (const auto& e : fs::directory_iterator(dir_)) EXPECT_EQ(e.path().filename(), "run.ckpt");
}

TEST_F(CheckpointTest, EmptySetRoundTrips) {
  const fs::path file = dir_ / "empty.ckpt";
  write_checkpoint(file, ParticleSet{}, RunClock{}, "");
  const CheckpointData d = read_checkpoint(file);
  EXPECT_EQ(d.particles.size(), 0u);
  EXPECT_EQ(d.clock.step, 0);
  EXPECT_TRUE(d.fingerprint.empty());
}

TEST_F(CheckpointTest, RejectsInconsistentParticleArrays) {
  ParticleSet p = awkward_particles(4);
  p.damage.pop_back();
  EXPECT_THROW(write_checkpoint(dir_ / "x.ckpt", p, RunClock{}, ""), std::invalid_argument);
  EXPECT_FALSE(fs::exists(dir_ / "x.ckpt"));
}

TEST_F(CheckpointTest, EachCorruptionGivesItsError) {
  const fs::path file = dir_ / "good.ckpt";
  write_checkpoint(file, awkward_particles(10), sample_clock(), "fingerprint");
  const std::string good = slurp(file);
  auto has = [](const std::string& message, const std::string& part) {
    return message.find(part) != std::string::npos;
  };

  const fs::path missing = dir_ / "missing.ckpt";
  std::string message;
  try {
    read_checkpoint(missing);
  } catch (const std::runtime_error& e) {
    message = e.what();
  }
  EXPECT_TRUE(has(message, missing.string()) && has(message, "does not exist")) << message;

  message = read_error("# a case file, not a checkpoint\n");
  EXPECT_TRUE(has(message, "bad.ckpt") && has(message, "not an ImpactSPH checkpoint")) << message;

  std::string other_version = good;
  const std::uint32_t version = kCheckpointVersion + 1;
  std::memcpy(other_version.data() + 14, &version, sizeof version);
  message = read_error(other_version);
  EXPECT_TRUE(has(message, "version " + std::to_string(version))) << message;

  message = read_error(good.substr(0, good.size() - 9));
  EXPECT_TRUE(has(message, "truncated")) << message;
  message = read_error(good.substr(0, 20));
  EXPECT_TRUE(has(message, "truncated")) << message;
  message = read_error(good.substr(0, 6));
  EXPECT_TRUE(has(message, "truncated")) << message;

  std::string flipped = good;
  flipped[good.size() / 2] ^= 0x10;
  message = read_error(flipped);
  EXPECT_TRUE(has(message, "checksum mismatch")) << message;
  flipped = good;
  flipped[good.size() - 1] ^= 0x01;  // the checksum itself
  message = read_error(flipped);
  EXPECT_TRUE(has(message, "checksum mismatch")) << message;

  message = read_error(good + "extra");
  EXPECT_TRUE(has(message, "beyond the end")) << message;

  EXPECT_EQ(read_error(good), "<no exception>");
}

}  // namespace
}  // namespace impactsph
