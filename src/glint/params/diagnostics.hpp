// Positions in scene files and the errors that point at them.
#pragma once

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace glint {

// The text of a scene (or mesh) file, kept so that an error can quote the offending line. The text is
// held once, as it is: splitting it into lines up front cost 32 bytes a line (2 GiB for a 64 MiB file
// of newlines), and a line is only looked for when an error is reported.
struct SourceFile {
    std::string path;
    std::string text;    // the lines from first_line on (the whole file, or an excerpt)
    int first_line = 1;  // the number of the first line of `text`

    static std::shared_ptr<const SourceFile> from_text(std::string path, const std::string& text);
    // Only some lines of a file (say, the one line of a large mesh file an error is about).
    static std::shared_ptr<const SourceFile> excerpt(std::string path, int first_line,
                                                     std::string_view lines);
    // Line `number` (1-based, without its end of line), or nullopt if the text does not hold it; of it,
    // at most `max_length` bytes from its byte `skip` on, found without reading the rest of the line
    // (the bytes skipped are taken to hold no line end: the caller knows the line is that long).
    std::optional<std::string_view> line(int number, std::size_t skip = 0,
                                         std::size_t max_length = std::string::npos) const;
};

// A 1-based line and column in a SourceFile. A default SourcePos means "no position known".
struct SourcePos {
    std::shared_ptr<const SourceFile> file;
    int line = 0;
    int column = 0;
};

// A mistake in the user's input. what() is the whole report:
//   scene.yaml:4:5: error: unknown key 'radious' in sphere; did you mean 'radius'?
//       radious: 1
//       ^
class SceneError : public std::runtime_error {
  public:
    SceneError(const SourcePos& pos, const std::string& message);
    const SourcePos& position() const { return pos_; }
    const std::string& message() const { return message_; }

  private:
    SourcePos pos_;
    std::string message_;
};

// The report SceneError carries: position, message, the line and a caret under the column.
// `severity` is the word after the position: "error" or "warning".
std::string format_diagnostic(const SourcePos& pos, const std::string& message,
                              const std::string& severity = "error");

// Something in the input that glint reads but does not render as its author meant: a construct an
// importer approximates or leaves out. Never an error (the scene still renders), never silent (it is
// printed as `file:line:col: warning: …` with the line and a caret).
struct SceneWarning {
    SourcePos pos;
    std::string message;

    std::string to_string() const { return format_diagnostic(pos, message, "warning"); }
};

// The closest of `candidates` to `word` by edit distance, or "" if none is close enough to suggest.
std::string closest_match(const std::string& word, const std::vector<std::string>& candidates);

// "a, b, c", for the lists of valid names in messages.
std::string join_words(const std::vector<std::string>& words);

// The message for a name that is not one of `known`:
//   unknown <what> '<word>'; did you mean '<closest>'? (<list_label>: a, b, c)
// The suggestion appears only when a known name is close.
std::string unknown_name_message(const std::string& what, const std::string& word,
                                 const std::vector<std::string>& known,
                                 const std::string& list_label = "known");

}  // namespace glint
