#include "common/checkpoint.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <type_traits>
#include <vector>

#include "common/output.hpp"

namespace impactsph {

namespace {

constexpr char kMagic[] = "IMPACTSPH-CKPT";
constexpr std::size_t kMagicSize = sizeof(kMagic) - 1;
constexpr std::uint32_t kByteOrderTag = 0x01020304u;
// magic, version, byte-order tag, four sizes, file size, particle count
constexpr std::size_t kHeaderSize = kMagicSize + 6 * sizeof(std::uint32_t) + 2 * sizeof(std::uint64_t);

// Arrays and the clock are copied raw, so their layouts are part of the format. The header records the
// type sizes, so a file from a build whose RunClock grew is refused on read; a change that keeps the sizes
// (reordered members) must bump kCheckpointVersion.
static_assert(sizeof(Vec3d) == 3 * sizeof(double) && std::is_trivially_copyable_v<Vec3d>);
static_assert(sizeof(Sym3d) == 6 * sizeof(double) && std::is_trivially_copyable_v<Sym3d>);
static_assert(std::is_trivially_copyable_v<RunClock>);

// Every ParticleSet array in file order (for_each_field, the order of IMPACTSPH_PARTICLE_FIELDS).
template <class Set, class F>
void for_each_array(Set& p, F&& f) {
  for_each_field(p, [&](const FieldInfo&, auto& a) { f(a); });
}

std::uint64_t bytes_per_particle() {
  std::uint64_t sum = 0;
  ParticleSet empty;
  for_each_array(empty, [&](const auto& a) { sum += sizeof(typename std::decay_t<decltype(a)>::value_type); });
  return sum;
}

std::uint64_t fnv1a64(const char* data, std::size_t size) {
  std::uint64_t h = 14695981039346656037ull;
  for (std::size_t i = 0; i < size; ++i) {
    h ^= static_cast<unsigned char>(data[i]);
    h *= 1099511628211ull;
  }
  return h;
}

class Writer {
 public:
  explicit Writer(std::size_t capacity) { bytes_.reserve(capacity); }
  void raw(const void* p, std::size_t n) {
    const char* c = static_cast<const char*>(p);
    bytes_.insert(bytes_.end(), c, c + n);
  }
  template <class T> void value(const T& v) { raw(&v, sizeof v); }
  std::vector<char>& bytes() { return bytes_; }

 private:
  std::vector<char> bytes_;
};

class Reader {
 public:
  Reader(const std::vector<char>& bytes, std::size_t end, const std::string& file)
      : bytes_(bytes), end_(end), file_(file) {}
  void raw(void* p, std::size_t n) {
    if (n == 0) return;
    if (n > end_ - pos_) throw std::runtime_error(file_ + ": inconsistent checkpoint layout (corrupted file)");
    std::memcpy(p, bytes_.data() + pos_, n);
    pos_ += n;
  }
  template <class T> T value() {
    T v;
    raw(&v, sizeof v);
    return v;
  }
  std::size_t position() const { return pos_; }
  void seek(std::size_t pos) { pos_ = pos; }

 private:
  const std::vector<char>& bytes_;
  std::size_t end_;
  std::size_t pos_ = 0;
  const std::string& file_;
};

}  // namespace

void write_checkpoint(const std::filesystem::path& file, const ParticleSet& p, const RunClock& clock,
                      const std::string& fingerprint) {
  const std::uint64_t n = p.size();
  for_each_array(p, [&](const auto& a) {
    if (a.size() != n)
      throw std::invalid_argument("write_checkpoint: particle arrays differ in length (" + std::to_string(a.size()) +
                                  " vs " + std::to_string(n) + ")");
  });
  const std::uint64_t total = kHeaderSize + n * bytes_per_particle() + sizeof(std::uint64_t) + sizeof(RunClock) +
                              sizeof(std::uint64_t) + fingerprint.size() + sizeof(std::uint64_t);

  Writer w(total);
  w.raw(kMagic, kMagicSize);
  w.value(kCheckpointVersion);
  w.value(kByteOrderTag);
  w.value(static_cast<std::uint32_t>(sizeof(double)));
  w.value(static_cast<std::uint32_t>(sizeof(Vec3d)));
  w.value(static_cast<std::uint32_t>(sizeof(Sym3d)));
  w.value(static_cast<std::uint32_t>(sizeof(RunClock)));
  w.value(total);
  w.value(n);
  for_each_array(p, [&](const auto& a) { w.raw(a.data(), a.size() * sizeof(a[0])); });
  w.value(static_cast<std::uint64_t>(p.rates_current ? 1 : 0));
  w.value(clock);
  w.value(static_cast<std::uint64_t>(fingerprint.size()));
  w.raw(fingerprint.data(), fingerprint.size());
  w.value(fnv1a64(w.bytes().data(), w.bytes().size()));
  write_binary_atomic(file, w.bytes());
}

CheckpointData read_checkpoint(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) throw std::runtime_error("checkpoint " + name + " does not exist");
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  if (!in) throw std::runtime_error("cannot open checkpoint " + name + ": " + std::strerror(errno));
  std::vector<char> bytes(static_cast<std::size_t>(in.tellg()));
  in.seekg(0);
  if (!in.read(bytes.data(), static_cast<std::streamsize>(bytes.size())))
    throw std::runtime_error("cannot read checkpoint " + name + ": " + std::strerror(errno));
  const std::size_t size = bytes.size();
  auto truncated = [&](std::uint64_t expected) {
    return std::runtime_error(name + ": truncated checkpoint (" + std::to_string(size) + " bytes, expected " +
                              (expected ? std::to_string(expected) : std::string("more")) + ")");
  };

  if (size > 0 && std::memcmp(bytes.data(), kMagic, std::min(size, kMagicSize)) != 0)
    throw std::runtime_error(name + ": not an ImpactSPH checkpoint");
  if (size < kHeaderSize) throw truncated(0);

  Reader r(bytes, size, name);
  r.seek(kMagicSize);
  const auto version = r.value<std::uint32_t>();
  if (version != kCheckpointVersion)
    throw std::runtime_error(name + ": checkpoint format version " + std::to_string(version) +
                             ", this build reads version " + std::to_string(kCheckpointVersion));
  if (r.value<std::uint32_t>() != kByteOrderTag)
    throw std::runtime_error(name + ": checkpoint written on a machine with another byte order");
  const std::uint32_t sizes[4] = {r.value<std::uint32_t>(), r.value<std::uint32_t>(), r.value<std::uint32_t>(),
                                  r.value<std::uint32_t>()};
  if (sizes[0] != sizeof(double) || sizes[1] != sizeof(Vec3d) || sizes[2] != sizeof(Sym3d) ||
      sizes[3] != sizeof(RunClock))
    throw std::runtime_error(name + ": checkpoint written by a build with other type sizes (double, Vec3d, Sym3d, "
                             "RunClock = " + std::to_string(sizes[0]) + ", " + std::to_string(sizes[1]) + ", " +
                             std::to_string(sizes[2]) + ", " + std::to_string(sizes[3]) + " bytes)");
  const auto total = r.value<std::uint64_t>();
  if (size < total) throw truncated(total);
  if (size > total)
    throw std::runtime_error(name + ": " + std::to_string(size - total) +
                             " bytes beyond the end of the checkpoint (corrupted file)");

  const std::size_t payload = size - sizeof(std::uint64_t);
  Reader tail(bytes, size, name);
  tail.seek(payload);
  if (tail.value<std::uint64_t>() != fnv1a64(bytes.data(), payload))
    throw std::runtime_error(name + ": checkpoint checksum mismatch (corrupted file)");

  // The checksum holds, so what follows fails only for a file written by a faulty writer.
  Reader body(bytes, payload, name);
  body.seek(r.position());
  const auto n = body.value<std::uint64_t>();
  if (n > (payload - kHeaderSize) / bytes_per_particle())
    throw std::runtime_error(name + ": inconsistent checkpoint layout (corrupted file)");
  CheckpointData out;
  out.particles.resize(static_cast<std::size_t>(n));
  for_each_array(out.particles, [&](auto& a) { body.raw(a.data(), a.size() * sizeof(a[0])); });
  const auto rates_current = body.value<std::uint64_t>();
  if (rates_current > 1) throw std::runtime_error(name + ": inconsistent checkpoint layout (corrupted file)");
  out.particles.rates_current = rates_current == 1;
  out.clock = body.value<RunClock>();
  const auto length = body.value<std::uint64_t>();
  if (length != payload - body.position())
    throw std::runtime_error(name + ": inconsistent checkpoint layout (corrupted file)");
  out.fingerprint.resize(static_cast<std::size_t>(length));
  body.raw(out.fingerprint.data(), out.fingerprint.size());
  return out;
}

}  // namespace impactsph
