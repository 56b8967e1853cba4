#pragma once
// A value or an error message: for operations with one way to fail (reading a file, say).
// Workspace checks that can find many problems return Diagnostics instead.

#include <cassert>
#include <string>
#include <utility>
#include <variant>

namespace rmfx {

struct Error {
    std::string message;
};

template <class T>
class Result {
public:
    Result(T value) : state_(std::move(value)) {}
    Result(Error error) : state_(std::move(error)) {}

    explicit operator bool() const { return state_.index() == 0; }
    bool ok() const { return state_.index() == 0; }

    T& value() { assert(ok()); return std::get<0>(state_); }
    const T& value() const { assert(ok()); return std::get<0>(state_); }
    T& operator*() { return value(); }
    const T& operator*() const { return value(); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }

    const std::string& error() const { assert(!ok()); return std::get<1>(state_).message; }

private:
    std::variant<T, Error> state_;
};

}  // namespace rmfx
