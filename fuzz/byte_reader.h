// The byte stream that the intersection fuzz targets decode into problems (target_curves.cpp, target_patches.cpp).
#ifndef BEZOUTIAN_FUZZ_BYTE_READER_H
#define BEZOUTIAN_FUZZ_BYTE_READER_H

#include <cstddef>
#include <cstdint>

namespace bezoutian {
namespace fuzz {

/// Reads the input a byte at a time; past the end every byte reads as 0, so that every input decodes to a problem.
class Byte_reader {
 public:
  Byte_reader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t next() { return pos_ < size_ ? data_[pos_++] : 0; }
  int next_signed() { return int(static_cast<std::int8_t>(next())); }

 private:
  const std::uint8_t* data_;
  std::size_t size_, pos_ = 0;
};

}  // namespace fuzz
}  // namespace bezoutian

#endif  // BEZOUTIAN_FUZZ_BYTE_READER_H
