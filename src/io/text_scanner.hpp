// Tokenising in-memory text for the ASCII readers (OBJ pre-scan, STL, PLY, OFF): tokens are
// string_views, numbers go through std::from_chars (locale-independent, no allocation, fast),
// and every error carries the line number.
#pragma once
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>

#include "inkshade/error.hpp"

namespace inkshade::io {

// `text` with its control characters as '?': values quoted in an error (a key "a\r", a field
// with a lone CR, a file name with a line break) cannot break the one-line message.
inline std::string one_line(std::string text) {
    for (char& c : text)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
    return text;
}

// A token as it may appear inside a one-line error message: control and non-ASCII bytes
// become '?', long tokens are cut.
inline std::string quote_token(std::string_view token) {
    std::string s;
    for (char c : token.substr(0, 24)) s += (c >= 0x20 && c < 0x7f) ? c : '?';
    if (token.size() > 24) s += "...";
    return "'" + s + "'";
}

// double -> float without the undefined behaviour of converting an out-of-range value:
// beyond float range becomes +-inf (and is then reported as non-finite), NaN stays NaN.
inline float to_float(double d) {
    constexpr double kMax = std::numeric_limits<float>::max();
    if (d > kMax) return std::numeric_limits<float>::infinity();
    if (d < -kMax) return -std::numeric_limits<float>::infinity();
    return static_cast<float>(d);
}

// Parses the whole token as T. A leading '+' is accepted (from_chars rejects it). Floating
// overflow yields +-inf and underflow 0, as strtod does, instead of failing, so the caller can
// report a non-finite value with its context; "nan" and "inf" parse too, for the same reason.
template <class T>
bool parse_number(std::string_view token, T& out) {
    const char* b = token.data();
    const char* e = b + token.size();
    if (b != e && *b == '+') {
        ++b;
        if (b == e || *b == '-') return false;
    }
    auto [ptr, ec] = std::from_chars(b, e, out);
    if constexpr (std::is_floating_point_v<T>) {
        if (ec == std::errc::result_out_of_range) {  // rare: let strtod pick inf or 0
            std::string copy(b, e);
            char* stop = nullptr;
            double d = std::strtod(copy.c_str(), &stop);
            out = static_cast<T>(std::is_same_v<T, float> ? to_float(d) : d);
            return stop == copy.c_str() + copy.size();
        }
    }
    return ec == std::errc() && ptr == e;
}

class TextScanner {
public:
    // comment: a character that starts a comment running to the end of the line ('\0': none).
    TextScanner(std::string_view text, std::string path, size_t first_line = 1, char comment = '\0')
        : p_(text.data()),
          end_(text.data() + text.size()),
          path_(std::move(path)),
          line_(first_line),
          comment_(comment) {}

    // Next token on the current line; empty at the end of the line (which is not consumed).
    std::string_view token_on_line() {
        skip_blanks();
        const char* b = p_;
        while (p_ != end_ && !is_space(*p_) && !is_comment(*p_)) ++p_;
        return {b, size_t(p_ - b)};
    }
    // Next token, crossing line ends; empty at the end of the text.
    std::string_view token() {
        for (;;) {
            skip_blanks();
            if (p_ == end_ || *p_ != '\n') return token_on_line();
            ++p_;
            ++line_;
        }
    }
    // True when only blanks (and a comment) remain on the current line.
    bool at_line_end() {
        skip_blanks();
        return p_ == end_ || *p_ == '\n';
    }
    // True when only whitespace and comments remain.
    bool at_end() {
        for (;;) {
            skip_blanks();
            if (p_ == end_) return true;
            if (*p_ != '\n') return false;
            ++p_;
            ++line_;
        }
    }
    // Moves past the next line end (or to the end of the text).
    void skip_line() {
        while (p_ != end_ && *p_ != '\n') ++p_;
        if (p_ != end_) {
            ++p_;
            ++line_;
        }
    }
    // The next token parsed as T; `what` names it in the error ("a vertex coordinate").
    template <class T>
    T number(const char* what) {
        std::string_view tok = token();
        T value{};
        if (tok.empty()) fail(std::string("unexpected end of file while reading ") + what);
        if (!parse_number(tok, value)) fail(std::string("expected ") + what + " but found " + quote_token(tok));
        return value;
    }
    // As number() but the token must be on the current line.
    template <class T>
    T number_on_line(const char* what) {
        if (at_line_end()) fail(std::string("line ends before ") + what);
        return number<T>(what);
    }

    size_t line() const { return line_; }
    size_t remaining() const { return size_t(end_ - p_); }
    [[noreturn]] void fail(const std::string& problem) const {
        throw InputError(path_, problem + " at line " + std::to_string(line_));
    }

private:
    static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }
    bool is_comment(char c) const { return comment_ != '\0' && c == comment_; }
    void skip_blanks() {
        while (p_ != end_) {
            char c = *p_;
            if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
                ++p_;
            } else if (is_comment(c)) {
                while (p_ != end_ && *p_ != '\n') ++p_;
            } else {
                break;
            }
        }
    }

    const char* p_;
    const char* end_;
    std::string path_;
    size_t line_;
    char comment_;
};

}  // namespace inkshade::io
