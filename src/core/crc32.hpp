#pragma once
// CRC-32 (the IEEE 802.3 / zlib / PNG polynomial 0xEDB88320, reflected, initial and final value
// 0xFFFFFFFF), for the checkpoint sections' checksums.
#include <cstddef>
#include <cstdint>

namespace mpdem {

// CRC of bytes [data, data + n), continuing from `crc` (the CRC of the bytes before; 0 to start).
std::uint32_t crc32(const void* data, std::size_t n, std::uint32_t crc = 0);

}  // namespace mpdem
