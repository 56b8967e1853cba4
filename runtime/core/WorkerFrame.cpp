#include "core/WorkerFrame.h"

#include <unistd.h>

#include <cerrno>
#include <cstdint>

namespace rmfx {

namespace {

std::uint64_t lengthAt(std::string_view header) {
    std::uint64_t length = 0;
    for (size_t i = 0; i < kWorkerFrameHeader; ++i) length |= std::uint64_t{static_cast<unsigned char>(header[i])} << (8 * i);
    return length;
}

// Reads exactly `size` bytes; the count read before an end of file or an error.
size_t readFully(int fd, char* into, size_t size) {
    size_t done = 0;
    while (done < size) {
        ssize_t n = ::read(fd, into + done, size - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        done += static_cast<size_t>(n);
    }
    return done;
}

}  // namespace

std::string frameMessage(std::string_view message) {
    std::string out(kWorkerFrameHeader, '\0');
    std::uint64_t length = message.size();
    for (size_t i = 0; i < kWorkerFrameHeader; ++i) out[i] = static_cast<char>((length >> (8 * i)) & 0xff);
    out.append(message);
    return out;
}

std::optional<std::string> takeFramedMessage(std::string& bytes, bool& broken) {
    broken = false;
    if (bytes.size() < kWorkerFrameHeader) return std::nullopt;
    std::uint64_t length = lengthAt(bytes);
    if (length > kWorkerFrameLimit) {
        broken = true;
        return std::nullopt;
    }
    if (bytes.size() - kWorkerFrameHeader < length) return std::nullopt;
    std::string message = bytes.substr(kWorkerFrameHeader, length);
    bytes.erase(0, kWorkerFrameHeader + length);
    return message;
}

FrameRead readFramedMessage(int fd, std::string& out) {
    char header[kWorkerFrameHeader];
    size_t got = readFully(fd, header, sizeof header);
    if (got == 0) return FrameRead::End;
    if (got < sizeof header) return FrameRead::Broken;
    std::uint64_t length = lengthAt({header, sizeof header});
    if (length > kWorkerFrameLimit) return FrameRead::Broken;
    out.resize(length);
    return readFully(fd, out.data(), length) == length ? FrameRead::Message : FrameRead::Broken;
}

bool writeAll(int fd, std::string_view bytes) {
    size_t written = 0;
    while (written < bytes.size()) {
        ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        written += static_cast<size_t>(n);
    }
    return true;
}

}  // namespace rmfx
