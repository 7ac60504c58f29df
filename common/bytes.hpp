#pragma once
// Binary state files and messages (a realization's mid-run checkpoint, run/checkpoint.hpp's
// in_flight_path; the MPI ranks' block results, run/mpi_ensemble.hpp): a writer that appends
// trivially copyable values and arrays of them in this machine's byte order, and a reader that
// checks every length against what is left, so a truncated or foreign file is refused with a
// message instead of being read past its end. A file is resumed only on the machine type that wrote
// it (the header records the sizes that must agree); the text checkpoints (run/checkpoint.hpp) are
// the portable record.
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace coldblast::common {

/// FNV-1a, 64 bits, of `size` bytes (the integrity check of a binary state file).
inline std::uint64_t fnv1a64(const void* data, std::size_t size, std::uint64_t hash = 0xcbf29ce484222325ULL) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t k = 0; k < size; ++k) hash = (hash ^ bytes[k]) * 0x100000001b3ULL;
  return hash;
}

class ByteWriter {
 public:
  template <class T>
  void put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    append(&value, sizeof(T));
  }
  /// The count, then the elements.
  template <class T, class Allocator>
  void put_vector(const std::vector<T, Allocator>& values) {
    static_assert(std::is_trivially_copyable_v<T>);
    put<std::uint64_t>(values.size());
    append(values.data(), values.size() * sizeof(T));
  }
  void put_string(const std::string& text) {
    put<std::uint64_t>(text.size());
    append(text.data(), text.size());
  }
  /// Bytes as they are, without their length (another writer's output, read on by the same reader).
  void put_raw(std::string_view bytes) { append(bytes.data(), bytes.size()); }
  /// Room for `more` bytes beyond those written (a large state grows without doubling its memory).
  void reserve(std::size_t more) { bytes_.reserve(bytes_.size() + more); }
  const std::string& bytes() const { return bytes_; }
  std::string take() { return std::move(bytes_); }

 private:
  void append(const void* data, std::size_t size) { bytes_.append(static_cast<const char*>(data), size); }
  std::string bytes_;
};

/// Reads what ByteWriter wrote; throws std::runtime_error naming `source` when the bytes run out.
/// It views the bytes, which must outlive it (a temporary string is refused at compile time).
class ByteReader {
 public:
  ByteReader(std::string_view bytes, std::string source) : bytes_(bytes), source_(std::move(source)) {}
  ByteReader(std::string&&, std::string) = delete;
  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    T value;
    std::memcpy(&value, take(sizeof(T)), sizeof(T));
    return value;
  }
  template <class T, class Allocator = std::allocator<T>>
  std::vector<T, Allocator> get_vector() {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto count = get<std::uint64_t>();
    if (count > (bytes_.size() - offset_) / (sizeof(T) ? sizeof(T) : 1)) fail("an array longer than the file");
    std::vector<T, Allocator> values(static_cast<std::size_t>(count));
    if (count > 0) std::memcpy(values.data(), take(static_cast<std::size_t>(count) * sizeof(T)), count * sizeof(T));
    return values;
  }
  std::string get_string() {
    const auto count = get<std::uint64_t>();
    if (count > bytes_.size() - offset_) fail("a text longer than the file");
    return std::string(take(static_cast<std::size_t>(count)), static_cast<std::size_t>(count));
  }
  std::size_t remaining() const { return bytes_.size() - offset_; }
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error(source_ + ": " + what + " at byte " + std::to_string(offset_));
  }

 private:
  const char* take(std::size_t size) {
    if (size > bytes_.size() - offset_) fail("truncated (" + std::to_string(size) + " bytes wanted)");
    const char* at = bytes_.data() + offset_;
    offset_ += size;
    return at;
  }
  std::string_view bytes_;
  std::string source_;
  std::size_t offset_ = 0;
};

}  // namespace coldblast::common
