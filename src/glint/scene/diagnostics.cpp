#include "glint/scene/diagnostics.hpp"

#include <algorithm>
#include <sstream>

namespace glint {

std::shared_ptr<const SourceFile> SourceFile::from_text(std::string path, const std::string& text) {
    auto file = std::make_shared<SourceFile>();
    file->path = std::move(path);
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        if (!line.empty() && line.back() == '\r') {
            line.pop_back();
        }
        file->lines.push_back(std::move(line));
    }
    return file;
}

std::string format_diagnostic(const SourcePos& pos, const std::string& message) {
    std::ostringstream out;
    if (pos.file) {
        out << pos.file->path << ':';
        if (pos.line > 0) {
            out << pos.line << ':' << pos.column << ':';
        }
        out << ' ';
    }
    out << "error: " << message;
    if (pos.file && pos.line > 0 && pos.line <= static_cast<int>(pos.file->lines.size())) {
        std::string text = pos.file->lines[static_cast<size_t>(pos.line - 1)];
        // The column comes from the parser and may lie past the end of our copy of the line (a
        // parser that counted characters of another encoding): keep it within the line.
        int column = std::clamp(pos.column, 1, static_cast<int>(text.size()) + 1);
        // A very long line (generated JSON, a minified file) is cut to a window around the column.
        constexpr int kWindow = 100;
        if (static_cast<int>(text.size()) > 2 * kWindow) {
            const int start = std::max(0, column - 1 - kWindow / 2);
            text = (start > 0 ? "..." : "") + text.substr(static_cast<size_t>(start), kWindow) + "...";
            column = column - start + (start > 0 ? 3 : 0);
        }
        // Control characters (a zero byte, an escape sequence) would garble the terminal: shown as '?'.
        for (char& c : text) {
            if ((static_cast<unsigned char>(c) < 0x20 && c != '\t') || c == 0x7f) {
                c = '?';
            }
        }
        out << "\n    " << text << "\n    ";
        // Keep tabs in the caret line so the caret sits under the right character.
        for (int i = 0; i + 1 < column && i < static_cast<int>(text.size()); ++i) {
            out << (text[static_cast<size_t>(i)] == '\t' ? '\t' : ' ');
        }
        out << '^';
    }
    return out.str();
}

SceneError::SceneError(const SourcePos& pos, const std::string& message)
    : std::runtime_error(format_diagnostic(pos, message)), pos_(pos), message_(message) {}

namespace {
size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) {
        row[j] = j;
    }
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t substitution = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
            diagonal = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
        }
    }
    return row[b.size()];
}
}  // namespace

std::string closest_match(const std::string& word, const std::vector<std::string>& candidates) {
    std::string best;
    // Suggest only what is close: up to two edits, or half the word for long words (rotation → rotate).
    size_t best_distance = std::max<size_t>(2, word.size() / 2) + 1;
    for (const std::string& candidate : candidates) {
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
