#include "glint/params/diagnostics.hpp"

#include <algorithm>
#include <sstream>

namespace glint {

std::shared_ptr<const SourceFile> SourceFile::from_text(std::string path, const std::string& text) {
    return excerpt(std::move(path), 1, text);
}

std::shared_ptr<const SourceFile> SourceFile::excerpt(std::string path, int first_line,
                                                      std::string_view lines) {
    auto file = std::make_shared<SourceFile>();
    file->path = std::move(path);
    file->text = std::string(lines);
    file->first_line = first_line;
    return file;
}

std::optional<std::string_view> SourceFile::line(int number, std::size_t skip, std::size_t max_length) const {
    if (number < first_line) {
        return std::nullopt;
    }
    std::size_t start = 0;
    for (int n = first_line; n < number; ++n) {
        const std::size_t end = text.find('\n', start);
        if (end == std::string::npos) {
            return std::nullopt;
        }
        start = end + 1;
    }
    if (start >= text.size() && !(start == 0 && number == first_line && !text.empty())) {
        return std::nullopt;  // past the last line (a final newline ends a line, it does not begin one)
    }
    const std::string_view from_start = std::string_view(text).substr(start);
    const std::string_view rest = from_start.substr(std::min(skip, from_start.size()), max_length);
    std::size_t end = rest.find('\n');
    end = end == std::string_view::npos ? rest.size() : end;
    if (end > 0 && rest[end - 1] == '\r') {
        --end;
    }
    return rest.substr(0, end);
}

std::string format_diagnostic(const SourcePos& pos, const std::string& message, const std::string& severity) {
    std::ostringstream out;
    if (pos.file) {
        out << pos.file->path << ':';
        if (pos.line > 0) {
            out << pos.line << ':' << pos.column << ':';
        }
        out << ' ';
    }
    out << severity << ": " << message;
    // A very long line (generated JSON, a minified file, a mesh on one line) is cut to a window around
    // the column, and nothing else of it is read: thousands of messages about one minified line would
    // otherwise each scan it.
    constexpr std::size_t kWindow = 100;
    const std::size_t column0 = static_cast<std::size_t>(std::max(pos.column, 1)) - 1;
    std::optional<std::string_view> part;  // far along a long line: the window, from its start
    if (pos.file && pos.line > 0 && column0 > 2 * kWindow) {
        part = pos.file->line(pos.line, column0 - kWindow / 2, kWindow);
        if (part && part->size() < kWindow / 2) {
            part.reset();  // the line ends before the column: read it from its start, as below
        }
    }
    std::string text;        // the line, or the window of it, to quote
    std::size_t column = 0;  // the caret's column in `text`, from 1; 0: nothing to quote
    if (part) {
        text = "..." + std::string(*part) + "...";
        column = kWindow / 2 + 4;
    } else if (const std::optional<std::string_view> line =
                   pos.file && pos.line > 0 ? pos.file->line(pos.line, 0, column0 + 2 * kWindow + 2)
                                            : std::optional<std::string_view>()) {
        const std::string_view whole = *line;
        // The column comes from the parser and may lie past the end of the line (a parser that
        // counted characters of another encoding): keep it within the line.
        const std::size_t column_in_line = std::min(column0 + 1, whole.size() + 1);
        column = column_in_line;
        if (whole.size() > 2 * kWindow) {
            const std::size_t start = column_in_line - 1 > kWindow / 2 ? column_in_line - 1 - kWindow / 2 : 0;
            text = (start > 0 ? "..." : "") + std::string(whole.substr(start, kWindow)) + "...";
            column = column_in_line - start + (start > 0 ? 3 : 0);
        } else {
            text = std::string(whole);
        }
    }
    if (column > 0) {
        // Control characters (a zero byte, an escape sequence) would garble the terminal: shown as '?'.
        for (char& c : text) {
            if ((static_cast<unsigned char>(c) < 0x20 && c != '\t') || c == 0x7f) {
                c = '?';
            }
        }
        out << "\n    " << text << "\n    ";
        // Keep tabs in the caret line so the caret sits under the right character.
        for (std::size_t i = 0; i + 1 < column && i < text.size(); ++i) {
            out << (text[i] == '\t' ? '\t' : ' ');
        }
        out << '^';
    }
    return out.str();
}

SceneError::SceneError(const SourcePos& pos, const std::string& message)
    : std::runtime_error(format_diagnostic(pos, message)), pos_(pos), message_(message) {}

namespace {
// Edits between two words, a swap of two neighbouring letters counting as one (the optimal string
// alignment distance): the commonest typo, `samplse` for `samples`, is then nearer to `samples` than to
// `sampler`.
size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
    for (size_t i = 0; i <= a.size(); ++i) {
        d[i][0] = i;
    }
    for (size_t j = 0; j <= b.size(); ++j) {
        d[0][j] = j;
    }
    for (size_t i = 1; i <= a.size(); ++i) {
        for (size_t j = 1; j <= b.size(); ++j) {
            d[i][j] = std::min(
                {d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
            }
        }
    }
    return d[a.size()][b.size()];
}
}  // namespace

std::string closest_match(const std::string& word, const std::vector<std::string>& candidates) {
    std::string best;
    // Suggest only what is close: up to two edits, or half the word for long words (rotation → rotate).
    size_t best_distance = std::max<size_t>(2, word.size() / 2) + 1;
    for (const std::string& candidate : candidates) {
        // Lengths that differ by the limit or more are that far apart at least; skipping them also
        // keeps the distance table small whatever the length of the word (a hostile file's key).
        const size_t length_difference =
            word.size() > candidate.size() ? word.size() - candidate.size() : candidate.size() - word.size();
        if (length_difference >= best_distance) {
            continue;
        }
        const size_t d = edit_distance(word, candidate);
        if (d < best_distance) {
            best_distance = d;
            best = candidate;
        }
    }
    return best;
}

std::string join_words(const std::vector<std::string>& words) {
    std::string out;
    for (const std::string& w : words) {
        out += (out.empty() ? "" : ", ") + w;
    }
    return out;
}

std::string unknown_name_message(const std::string& what, const std::string& word,
                                 const std::vector<std::string>& known, const std::string& list_label) {
    std::string message = "unknown " + what + " '" + word + "'";
    const std::string guess = closest_match(word, known);
    if (!guess.empty()) {
        message += "; did you mean '" + guess + "'?";
    }
    return message + " (" + list_label + ": " + join_words(known) + ")";
}

}  // namespace glint
