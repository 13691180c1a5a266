// Two inputs toml++ 3.3 (Debian 12) mishandles, refused before it sees them (found by fuzzing):
// - A non-ASCII character where toml++ tests for whitespace (after a key, inside a bare value
//   such as a number, after a backslash in a multi-line string) goes to a generated function
//   that reaches __builtin_unreachable for most code points: undefined behaviour. TOML allows
//   non-ASCII characters only in strings and comments, so this walks the TOML grammar (keys,
//   values, arrays, inline tables, table headers) far enough to know where strings are, as
//   toml++ does: a quote inside a bare value (`0["é`) does not start one. Anything unexpected
//   is a syntax error toml++ reports; the rest of that line may hold no non-ASCII character.
// - A dotted key nests a table per dot, and toml++ builds and frees them recursively: a 600 KB
//   key `a.a.a...` overflowed the stack. Keys lie on one line, so at most kMaxDotsPerLine dots
//   per line outside strings and comments (a style's longest number list has 16).
#include "styles/toml_prelexer.hpp"

#include <vector>

#include "inkshade/error.hpp"

namespace inkshade::styles {
namespace {

constexpr size_t kMaxDotsPerLine = 128;

bool non_ascii(char c) { return static_cast<unsigned char>(c) >= 0x80; }
bool blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }
bool key_char(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
}

class TomlPrelexer {
public:
    TomlPrelexer(std::string_view text, const std::string& source)
        : text_(text), source_(source), i_(text.starts_with("\xEF\xBB\xBF") ? 3 : 0) {}

    void run() {
        while (i_ < text_.size()) {
            const char c = text_[i_];
            if (c == '\n') {
                ++line_, ++i_, dots_ = 0;
                if (nest_.empty() || mode_ == Mode::Strict)
                    mode_ = nest_.empty() ? Mode::Key : Mode::Value, header_ = false;
                continue;
            }
            if (mode_ == Mode::Strict) {
                if (non_ascii(c)) fail("outside a string or comment (keys and values are ASCII)");
                if (c == '.') dot();
                ++i_;
                continue;
            }
            if (blank(c)) {
                ++i_;
            } else if (c == '#') {
                while (i_ < text_.size() && text_[i_] != '\n') ++i_;
            } else if (non_ascii(c)) {
                fail("outside a string or comment (keys and values are ASCII)");
            } else if (mode_ == Mode::Key) {
                key(c);
            } else if (mode_ == Mode::Value) {
                value(c);
            } else {
                after_value(c);
            }
        }
    }

private:
    enum class Mode { Key, Value, AfterValue, Strict };  // Strict: what is left of a line after a syntax error

    [[noreturn]] void fail(const char* where) const {
        throw InputError(source_, "line " + std::to_string(line_) + ": non-ASCII character " + where);
    }
    void dot() {
        if (++dots_ > kMaxDotsPerLine)
            throw InputError(source_, "line " + std::to_string(line_) + ": more than " +
                                          std::to_string(kMaxDotsPerLine) +
                                          " dots outside strings (keys nest at most that deep)");
    }
    bool at(size_t k, std::string_view s) const { return text_.substr(k, s.size()) == s; }

    // A string starting at the quote text_[i_]; leaves i_ after it.
    void string() {
        const char q = text_[i_];
        const bool multi_line = at(i_, q == '"' ? "\"\"\"" : "'''");
        const std::string_view end = multi_line ? text_.substr(i_, 3) : text_.substr(i_, 1);
        for (i_ += end.size(); i_ < text_.size() && !at(i_, end) && (multi_line || text_[i_] != '\n'); ++i_) {
            if (text_[i_] == '\n') ++line_;
            if (q != '"' || text_[i_] != '\\' || i_ + 1 >= text_.size()) continue;
            ++i_;  // an escaped character
            if (!multi_line) continue;
            if (non_ascii(text_[i_])) fail("after a backslash in a multi-line string");
            if (blank(text_[i_]) || text_[i_] == '\n') {  // a line-ending backslash: blanks and line breaks are skipped
                while (i_ < text_.size() && (blank(text_[i_]) || text_[i_] == '\n')) line_ += text_[i_++] == '\n';
                if (i_ < text_.size() && non_ascii(text_[i_])) fail("after a line-ending backslash");
                --i_;
            }
        }
        // The closing delimiter; a multi-line string's may have up to two more quotes.
        for (size_t n = 0; i_ < text_.size() && text_[i_] == q && n < (multi_line ? 5u : 1u); ++n) ++i_;
    }

    Mode close(char open) {  // ']' or '}' closing nest_.back()
        if (nest_.empty() || nest_.back() != open) return Mode::Strict;
        nest_.pop_back();
        return Mode::AfterValue;
    }

    void key(char c) {
        if (key_char(c)) {
            while (i_ < text_.size() && key_char(text_[i_])) ++i_;
        } else if (c == '"' || c == '\'') {
            string();
        } else if (c == '.') {
            dot(), ++i_;
        } else if (c == '[' && nest_.empty() && !header_) {  // [table] or [[array of tables]]
            header_ = true;
            i_ += at(i_, "[[") ? 2 : 1;
        } else if (c == ']' && header_) {
            header_ = false;
            i_ += at(i_, "]]") ? 2 : 1;
            mode_ = Mode::AfterValue;
        } else if (c == '=' && !header_) {
            mode_ = Mode::Value, ++i_;
        } else if (c == '}') {  // {} or a trailing comma
            mode_ = close('{'), ++i_;
        } else {
            mode_ = Mode::Strict;
        }
    }

    void value(char c) {
        if (c == '"' || c == '\'') {
            string();
            mode_ = Mode::AfterValue;
        } else if (c == '[' || c == '{') {
            nest_.push_back(c), ++i_;
            mode_ = c == '[' ? Mode::Value : Mode::Key;
        } else if (c == ']') {  // [] or a trailing comma
            mode_ = close('['), ++i_;
        } else {  // a bare value (number, date, boolean): toml++ reads it up to a terminator
            for (; i_ < text_.size() && !blank(text_[i_]) && text_[i_] != '\n' && text_[i_] != ']' &&
                   text_[i_] != '}' && text_[i_] != ',' && text_[i_] != '#';
                 ++i_) {
                if (non_ascii(text_[i_])) fail("outside a string or comment (keys and values are ASCII)");
                if (text_[i_] == '.') dot();
            }
            mode_ = Mode::AfterValue;
        }
    }

    void after_value(char c) {
        if (c == ',' && !nest_.empty())
            mode_ = nest_.back() == '[' ? Mode::Value : Mode::Key;
        else if (c == ']')
            mode_ = close('[');
        else if (c == '}')
            mode_ = close('{');
        else
            mode_ = Mode::Strict;
        if (mode_ != Mode::Strict) ++i_;
    }

    const std::string_view text_;
    const std::string& source_;
    size_t i_, line_ = 1, dots_ = 0;
    std::vector<char> nest_;  // open arrays '[' and inline tables '{'
    Mode mode_ = Mode::Key;
    bool header_ = false;  // inside [table] or [[array of tables]]
};

}  // namespace

void check_toml_text(std::string_view text, const std::string& source) { TomlPrelexer(text, source).run(); }

}  // namespace inkshade::styles
