#pragma once
// How rmfx and a helper program that lives for the run (core/IsolatedWorker.h) tell one message
// from the next on a byte stream: each message is its length (8 bytes, least significant first)
// followed by that many bytes. Only the standard library and POSIX: the helper programs are built
// from this file and their own.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace rmfx {

constexpr size_t kWorkerFrameHeader = 8;
// More than any shader or SPIR-V module; a longer length is a stream that is not this protocol.
constexpr size_t kWorkerFrameLimit = size_t{1} << 30;

// `message` with its length in front.
std::string frameMessage(std::string_view message);

// The message at the start of `bytes` once all of it is there, with `bytes` past it; nullopt
// while it is incomplete. `broken` is set for a length over kWorkerFrameLimit.
std::optional<std::string> takeFramedMessage(std::string& bytes, bool& broken);

enum class FrameRead { Message, End, Broken };

// Blocking, for the helper program's side: one message from `fd` into `out`. End for an end of
// file before a message starts; Broken for one inside a message, a read error or a bad length.
FrameRead readFramedMessage(int fd, std::string& out);

// Blocking: all of `bytes` to `fd`; false on an error (the reader has gone).
bool writeAll(int fd, std::string_view bytes);

}  // namespace rmfx
