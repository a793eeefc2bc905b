#pragma once
// A DS whose largest arrays are not to be held whole: their payload is handed over piece by
// piece as it comes off the disk, and the reader keeps what it needs (a rank of a distributed
// solve keeps its rows' entries of a TAE of hundreds of MB, assembly/tae.cpp).
#include "core/ds.hpp"

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>

namespace sig {

/// Takes the payload of a streamed array: `array` carries its name, type and shape (no bytes),
/// `piece` `size` bytes of whole values; the pieces come in order.
using DsPieces = std::function<void(const DsArray& array, const char* piece, std::size_t size)>;

/// The largest piece handed to a DsPieces: 1 MiB.
inline constexpr std::size_t kDsPieceBytes = std::size_t{1} << 20;

/// read_ds of the arrays `wanted` selects, but those `streamed` selects go to `take` in pieces
/// and are not kept (asking the Ds for one is an error saying "missing"). Same checks as read_ds;
/// a streamed array's CRC is checked after its last piece, so a caller drops what it took when
/// this throws.
Ds read_ds_streamed(const std::filesystem::path& path, const std::string& expected_kind,
                    const DsSelection& wanted, const DsSelection& streamed, const DsPieces& take);

/// read_ds_streamed without registering the DS as an input of the case (as read_ds_record): a
/// rank's part of a distributed DS, which its reader checks against the index it registered
/// (assembly/tae_parts.hpp), so that the case's files keep one file per kind.
Ds read_ds_record_streamed(const std::filesystem::path& path, const std::string& expected_kind,
                           const DsSelection& wanted, const DsSelection& streamed,
                           const DsPieces& take);

} // namespace sig
