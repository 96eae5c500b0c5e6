// InputError: a problem with something the user gave us (a file, a flag), reported as one line.
// Not for programmer errors; those are CHECKs (util/check.h).
//
// what() is a C string that Python reads as UTF-8, so each of these writes a NUL and any byte that is not
// UTF-8 from a user string as \xNN in its message (escapeForMessage, util/error_line.h): "renderer: unknown
// value 'trace\x00x'" keeps what follows the NUL, and a JSON parse error quoting a stray 0xFF byte reaches
// Python as text. Printing escapes the control characters (errorLine).
#pragma once

#include "util/error_line.h"

#include <stdexcept>
#include <string>

namespace shadelab {

// Message format: "<file>: <place>: <reason>", with place omitted when unknown.
class InputError : public std::runtime_error {
public:
    InputError(const std::string& file, const std::string& place, const std::string& reason)
        : std::runtime_error(escapeForMessage(format(file, place, reason))), file_(file) {}
    InputError(const std::string& file, const std::string& reason) : InputError(file, "", reason) {}

    const std::string& file() const { return file_; }

private:
    static std::string format(const std::string& file, const std::string& place, const std::string& reason) {
        std::string s = file.empty() ? std::string() : file + ": ";
        if (!place.empty()) s += place + ": ";
        return s + reason;
    }
    std::string file_;
};

// A usage error (bad flag or argument): exit code 2.
class UsageError : public std::runtime_error {
public:
    explicit UsageError(const std::string& message) : std::runtime_error(escapeForMessage(message)) {}
};

// A setting out of its range, thrown by the libraries and named by its field as a render request names it
// ("spp", "size", "depth"; render/render_request.h), never by a front end's spelling of it. Each front end
// words it its own way: `--spp: ...` on the command line, `spp: ...` in Python, `actions[3].spp: ...` in a
// viewer script. what() is "<field>: <reason>".
class SettingError : public std::invalid_argument {
public:
    SettingError(const std::string& field, const std::string& reason)
        : std::invalid_argument(escapeForMessage(field + ": " + reason)),
          field_(escapeForMessage(field)),
          reason_(escapeForMessage(reason)) {}

    const std::string& field() const { return field_; }
    const std::string& reason() const { return reason_; }

private:
    std::string field_, reason_;
};

}  // namespace shadelab
