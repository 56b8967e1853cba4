#pragma once
// The library's one error shape: a value, or the diagnostics that say why there is none.
//
// Result<T> holds a T and any warnings, or at least one error (with any warnings found before it).
// Result<void> is the same without a value. An operation with one way to fail (reading a file)
// returns Error{"message"}; one that can find many problems in user input (parsing a workspace)
// returns its Diagnostics, each naming the file, line and element.

#include <cassert>
#include <optional>
#include <string>
#include <utility>

#include "core/Diagnostic.h"

namespace rmfx {

// One problem without a location of its own: the caller knows what was being done (the file
// being read, say) and the message says what went wrong.
struct Error {
    std::string message;
};

namespace detail {

// What Result<T> and Result<void> share: the diagnostics, and whether there is an error.
class ResultDiagnostics {
public:
    // A temporary's diagnostics and error text come by value, so that
    // `for (const Diagnostic& d : f().diagnostics())` does not read a destroyed Result.
    const Diagnostics& diagnostics() const& { return diagnostics_; }
    Diagnostics diagnostics() && { return std::move(diagnostics_); }
    Diagnostics takeDiagnostics() { return std::move(diagnostics_); }
    // The errors' messages, one per line (as Error gave them, or formatted with their location).
    const std::string& error() const& { return error_; }
    std::string error() && { return std::move(error_); }

protected:
    ResultDiagnostics() = default;
    explicit ResultDiagnostics(Diagnostics diagnostics) : diagnostics_(std::move(diagnostics)) {}
    explicit ResultDiagnostics(Error e) : error_(std::move(e.message)) {
        diagnostics_.push_back({Diagnostic::Severity::Error, {}, "", error_});
    }
    // A failure from diagnostics: they must hold an error.
    void failWith(Diagnostics diagnostics) {
        assert(hasErrors(diagnostics));
        diagnostics_ = std::move(diagnostics);
        for (const Diagnostic& d : diagnostics_) {
            if (d.severity != Diagnostic::Severity::Error) continue;
            if (!error_.empty()) error_ += '\n';
            error_ += d.where.file.empty() && d.element.empty() ? d.message : d.format();
        }
    }

    Diagnostics diagnostics_;
    std::string error_;
};

}  // namespace detail

template <class T>
class [[nodiscard]] Result : public detail::ResultDiagnostics {
public:
    Result(T value, Diagnostics warnings = {}) : ResultDiagnostics(std::move(warnings)), value_(std::move(value)) {
        assert(!hasErrors(diagnostics_));
    }
    Result(Error error) : ResultDiagnostics(std::move(error)) {}
    // Diagnostics with at least one error: a failure.
    static Result failure(Diagnostics diagnostics) {
        Result r;
        r.failWith(std::move(diagnostics));
        return r;
    }

    explicit operator bool() const { return value_.has_value(); }
    bool ok() const { return value_.has_value(); }

    T& value() { assert(ok()); return *value_; }
    const T& value() const { assert(ok()); return *value_; }
    T& operator*() { return value(); }
    const T& operator*() const { return value(); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }

private:
    Result() = default;
    std::optional<T> value_;
};

template <>
class [[nodiscard]] Result<void> : public detail::ResultDiagnostics {
public:
    // Success, with any warnings; a failure when they hold an error.
    Result(Diagnostics warnings = {}) {
        if (hasErrors(warnings)) {
            failWith(std::move(warnings));
            failed_ = true;
        } else {
            diagnostics_ = std::move(warnings);
        }
    }
    Result(Error error) : ResultDiagnostics(std::move(error)), failed_(true) {}
    static Result failure(Diagnostics diagnostics) {
        Result r;
        r.failWith(std::move(diagnostics));
        r.failed_ = true;
        return r;
    }

    // Decided once: taking the diagnostics away does not turn a failure into a success.
    explicit operator bool() const { return ok(); }
    bool ok() const { return !failed_; }

private:
    bool failed_ = false;
};

}  // namespace rmfx
