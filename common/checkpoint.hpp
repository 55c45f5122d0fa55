// Checkpoints (host only): the whole ParticleSet and RunClock in one binary file, so a restarted run
// continues bit for bit. Layout (native byte order, checked on read):
//   "IMPACTSPH-CKPT", u32 format version, u32 byte-order tag, u32 sizeof(double, Vec3d, Sym3d, RunClock),
//   u64 file size, u64 particle count, every ParticleSet array raw, u64 rates_current (0 or 1), RunClock raw,
//   u64 fingerprint length + bytes, u64 FNV-1a 64 of everything before it.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>

#include "common/particle_set.hpp"
#include "common/run_state.hpp"

namespace impactsph {

inline constexpr std::uint32_t kCheckpointVersion = 5;  // 5: the leapfrog's carried rates

struct CheckpointData {
  ParticleSet particles;
  RunClock clock;
  std::string fingerprint;  // what the run was started from (case, build); the caller compares it
};

// Written atomically (temporary name, fsync, rename). Throws std::invalid_argument when the arrays of
// `p` differ in length, std::runtime_error when the file cannot be written.
void write_checkpoint(const std::filesystem::path& file, const ParticleSet& p, const RunClock& clock,
                      const std::string& fingerprint);

// Throws std::runtime_error naming the file for a missing file, a file that is not a checkpoint, another
// format version, byte order or type sizes, a truncated file and a checksum mismatch.
CheckpointData read_checkpoint(const std::filesystem::path& file);

}  // namespace impactsph
