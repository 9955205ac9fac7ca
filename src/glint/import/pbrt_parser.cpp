// The pbrt-v4 tokenizer and statement parser (the syntax of pbrt-v4's file format, as its parser.cpp
// reads it): tokens are quoted strings (with \n \t \\ \" … escapes, never across a line), `[` and `]`,
// `#` comments to the end of the line, and bare words (directives, numbers, true/false).
#include "glint/import/pbrt_parser.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>
#include <string_view>

namespace glint {
namespace {

struct Token {
    enum class Kind { Word, String, Open, Close, End };
    Kind kind = Kind::End;
    std::string text;  // a string's text unescaped; a word as written
    SourcePos pos;
};

class Tokenizer {
  public:
    explicit Tokenizer(std::shared_ptr<const SourceFile> file) : file_(std::move(file)), text_(file_->text) {}

    const Token& peek() {
        if (!peeked_) {
            next_ = read();
            peeked_ = true;
        }
        return next_;
    }
    Token take() {
        peek();
        peeked_ = false;
        return std::move(next_);
    }
    SourcePos here() const { return {file_, line_, column_}; }

  private:
    char advance() {
        const char c = text_[at_++];
        if (c == '\n') {
            ++line_;
            column_ = 1;
        } else {
            ++column_;
        }
        return c;
    }

    Token read() {
        // Blanks and comments.
        while (at_ < text_.size()) {
            const char c = text_[at_];
            if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
                advance();
            } else if (c == '#') {
                while (at_ < text_.size() && text_[at_] != '\n' && text_[at_] != '\r') {
                    advance();
                }
            } else {
                break;
            }
        }
        Token token;
        token.pos = here();
        if (at_ >= text_.size()) {
            return token;
        }
        const char c = advance();
        if (c == '[' || c == ']') {
            token.kind = c == '[' ? Token::Kind::Open : Token::Kind::Close;
            token.text = std::string(1, c);
        } else if (c == '"') {
            token.kind = Token::Kind::String;
            read_string(token);
        } else {
            token.kind = Token::Kind::Word;
            const std::size_t start = at_ - 1;
            while (at_ < text_.size()) {
                const char d = text_[at_];
                if (d == ' ' || d == '\t' || d == '\n' || d == '\r' || d == '"' || d == '[' || d == ']') {
                    break;
                }
                advance();
            }
            token.text = text_.substr(start, at_ - start);
        }
        return token;
    }

    void read_string(Token& token) {
        while (true) {
            if (at_ >= text_.size()) {
                throw SceneError(token.pos, "the quoted string is not closed before the end of the file");
            }
            const SourcePos at = here();
            const char c = advance();
            if (c == '"') {
                return;
            }
            if (c == '\n' || c == '\r') {
                throw SceneError(token.pos, "the quoted string is not closed on its line");
            }
            if (c != '\\') {
                token.text += c;
                continue;
            }
            if (at_ >= text_.size()) {
                throw SceneError(token.pos, "the quoted string is not closed before the end of the file");
            }
            const char escaped = advance();
            // pbrt's escapes, as pairs: the letter after the backslash, then what it stands for.
            constexpr std::string_view kEscapes = "b\bf\fn\nr\rt\t\\\\''\"\"";
            std::size_t at_pair = 0;
            while (at_pair < kEscapes.size() && kEscapes[at_pair] != escaped) {
                at_pair += 2;
            }
            if (at_pair >= kEscapes.size()) {
                throw SceneError(at, std::string("unknown escape '\\") + escaped +
                                         "' in a quoted string (known: \\b \\f \\n \\r \\t \\\\ \\' \\\")");
            }
            token.text += kEscapes[at_pair + 1];
        }
    }

    std::shared_ptr<const SourceFile> file_;
    const std::string& text_;
    std::size_t at_ = 0;
    int line_ = 1, column_ = 1;
    Token next_;
    bool peeked_ = false;
};

// What a directive takes before its parameter list.
struct Signature {
    const char* name;
    int strings;           // quoted strings
    int numbers;           // numbers (Transform's 16 may stand in [ ])
    bool params;           // a parameter list follows
    bool optional_string;  // one more quoted string may follow (MediumInterface)
    bool bare_word;        // the argument is a bare word (ActiveTransform All)
};

constexpr Signature kDirectives[] = {
    {"Accelerator", 1, 0, true, false, false},
    {"ActiveTransform", 0, 0, false, false, true},
    {"AreaLightSource", 1, 0, true, false, false},
    {"Attribute", 1, 0, true, false, false},
    {"AttributeBegin", 0, 0, false, false, false},
    {"AttributeEnd", 0, 0, false, false, false},
    {"Camera", 1, 0, true, false, false},
    {"ColorSpace", 1, 0, false, false, false},
    {"ConcatTransform", 0, 16, false, false, false},
    {"CoordinateSystem", 1, 0, false, false, false},
    {"CoordSysTransform", 1, 0, false, false, false},
    {"Film", 1, 0, true, false, false},
    {"Identity", 0, 0, false, false, false},
    {"Import", 1, 0, false, false, false},
    {"Include", 1, 0, false, false, false},
    {"Integrator", 1, 0, true, false, false},
    {"LightSource", 1, 0, true, false, false},
    {"LookAt", 0, 9, false, false, false},
    {"MakeNamedMaterial", 1, 0, true, false, false},
    {"MakeNamedMedium", 1, 0, true, false, false},
    {"Material", 1, 0, true, false, false},
    {"MediumInterface", 1, 0, false, true, false},
    {"NamedMaterial", 1, 0, false, false, false},
    {"ObjectBegin", 1, 0, false, false, false},
    {"ObjectEnd", 0, 0, false, false, false},
    {"ObjectInstance", 1, 0, false, false, false},
    {"Option", 0, 0, true, false, false},
    {"PixelFilter", 1, 0, true, false, false},
    {"ReverseOrientation", 0, 0, false, false, false},
    {"Rotate", 0, 4, false, false, false},
    {"Sampler", 1, 0, true, false, false},
    {"Scale", 0, 3, false, false, false},
    {"Shape", 1, 0, true, false, false},
    {"Texture", 3, 0, true, false, false},
    {"Transform", 0, 16, false, false, false},
    {"TransformBegin", 0, 0, false, false, false},
    {"TransformEnd", 0, 0, false, false, false},
    {"TransformTimes", 0, 2, false, false, false},
    {"Translate", 0, 3, false, false, false},
    {"WorldBegin", 0, 0, false, false, false},
    {"WorldEnd", 0, 0, false, false, false},
};

// The parameter types and how many numbers (or strings) make one value of each.
struct ParamType {
    const char* name;
    enum class Values { Numbers, Strings, Booleans, Spectrum } values;
    int arity;  // numbers per value
};
constexpr ParamType kParamTypes[] = {
    {"integer", ParamType::Values::Numbers, 1},   {"float", ParamType::Values::Numbers, 1},
    {"point2", ParamType::Values::Numbers, 2},    {"vector2", ParamType::Values::Numbers, 2},
    {"point3", ParamType::Values::Numbers, 3},    {"vector3", ParamType::Values::Numbers, 3},
    {"normal3", ParamType::Values::Numbers, 3},   {"normal", ParamType::Values::Numbers, 3},
    {"point", ParamType::Values::Numbers, 3},     {"vector", ParamType::Values::Numbers, 3},
    {"rgb", ParamType::Values::Numbers, 3},       {"color", ParamType::Values::Numbers, 3},
    {"blackbody", ParamType::Values::Numbers, 1}, {"spectrum", ParamType::Values::Spectrum, 2},
    {"bool", ParamType::Values::Booleans, 1},     {"string", ParamType::Values::Strings, 1},
    {"texture", ParamType::Values::Strings, 1},
};

std::vector<std::string> directive_names() {
    std::vector<std::string> names;
    for (const Signature& s : kDirectives) {
        names.emplace_back(s.name);
    }
    return names;
}

std::vector<std::string> param_type_names() {
    std::vector<std::string> names;
    for (const ParamType& t : kParamTypes) {
        names.emplace_back(t.name);
    }
    return names;
}

std::string describe(const Token& token) {
    switch (token.kind) {
        case Token::Kind::End:
            return "the end of the file";
        case Token::Kind::String:
            return "the string \"" + token.text + "\"";
        default:
            return "'" + token.text + "'";
    }
}

// A finite number written as pbrt writes them, or nothing.
bool parse_number(const std::string& text, double& value) {
    const char* begin = text.data();
    const char* end = begin + text.size();
    if (begin != end && *begin == '+') {
        ++begin;  // from_chars takes no plus sign; pbrt's number parser does
    }
    const auto [stop, error] = std::from_chars(begin, end, value);
    return error == std::errc() && stop == end && std::isfinite(value);
}

class Parser {
  public:
    Parser(const std::filesystem::path& search_dir, const std::function<void(PbrtStatement&)>& statement,
           const PbrtLimits& limits)
        : search_dir_(search_dir), statement_(statement), limits_(limits) {}

    void parse_file(const std::filesystem::path& path, const SourcePos& mentioned_at, int depth) {
        const std::string shown = path.generic_string();
        std::error_code ec;
        if (!std::filesystem::is_regular_file(path, ec)) {
            throw SceneError(mentioned_at, "cannot read '" + shown + "': " +
                                               (std::filesystem::exists(path, ec) ? "it is not a regular file"
                                                                                  : "it does not exist"));
        }
        const std::uintmax_t size = std::filesystem::file_size(path, ec);
        if (ec || size > limits_.max_file_bytes) {
            throw SceneError(mentioned_at, ec ? "cannot read '" + shown + "': " + ec.message()
                                              : "'" + shown + "' is " + std::to_string(size) +
                                                    " bytes, more than " +
                                                    std::to_string(limits_.max_file_bytes) +
                                                    " (the largest scene file glint reads)");
        }
        std::ifstream in(path, std::ios::binary);
        std::string text(static_cast<std::size_t>(size), '\0');
        if (!in.read(text.data(), static_cast<std::streamsize>(size))) {
            throw SceneError(mentioned_at, "cannot read '" + shown + "'");
        }
        parse_text(text, shown, mentioned_at, depth);
    }

    void parse_text(const std::string& text, const std::string& shown, const SourcePos& mentioned_at,
                    int depth) {
        ++files_;
        total_bytes_ += text.size();
        if (files_ > limits_.max_files) {
            throw SceneError(mentioned_at, "more than " + std::to_string(limits_.max_files) +
                                               " files included in all (an Include that repeats itself?)");
        }
        if (total_bytes_ > limits_.max_total_bytes) {
            throw SceneError(mentioned_at, "the scene and its included files add up to more than " +
                                               std::to_string(limits_.max_total_bytes) + " bytes");
        }
        if (text.find('\0') != std::string::npos) {
            throw SceneError(mentioned_at,
                             "'" + shown + "' holds a zero byte: it is not a pbrt scene (text)");
        }
        Tokenizer tokens(SourceFile::from_text(shown, text));
        while (tokens.peek().kind != Token::Kind::End) {
            read_statement(tokens, depth);
        }
    }

  private:
    void read_statement(Tokenizer& tokens, int depth) {
        Token word = tokens.take();
        if (word.kind != Token::Kind::Word) {
            throw SceneError(word.pos, "expected a directive (Shape, LookAt, …), found " + describe(word));
        }
        const Signature* signature = nullptr;
        for (const Signature& s : kDirectives) {
            if (word.text == s.name) {
                signature = &s;
            }
        }
        if (!signature) {
            throw SceneError(word.pos, unknown_name_message("directive", word.text, directive_names()));
        }
        PbrtStatement statement;
        statement.directive = word.text;
        statement.pos = word.pos;
        if (signature->bare_word) {
            Token arg = tokens.take();
            if (arg.kind != Token::Kind::Word) {
                throw SceneError(
                    arg.pos, word.text + " takes a word (All, StartTime, EndTime), found " + describe(arg));
            }
            statement.strings.push_back(arg.text);
        }
        for (int i = 0; i < signature->strings; ++i) {
            statement.strings.push_back(take_string(tokens, word.text));
        }
        if (signature->optional_string && tokens.peek().kind == Token::Kind::String) {
            statement.strings.push_back(tokens.take().text);
        }
        if (signature->numbers > 0) {
            read_arguments(tokens, statement, signature->numbers);
        }
        if (signature->params) {
            while (tokens.peek().kind == Token::Kind::String) {
                statement.params.push_back(read_param(tokens));
            }
        }
        if (statement.directive == "Include" || statement.directive == "Import") {
            include(statement, depth);
            return;
        }
        statement_(statement);
    }

    std::string take_string(Tokenizer& tokens, const std::string& directive) {
        Token arg = tokens.take();
        if (arg.kind != Token::Kind::String) {
            throw SceneError(arg.pos, directive + " takes a quoted string here, found " + describe(arg));
        }
        return arg.text;
    }

    void read_arguments(Tokenizer& tokens, PbrtStatement& statement, int count) {
        const bool bracketed = tokens.peek().kind == Token::Kind::Open;
        if (bracketed) {
            tokens.take();
        }
        for (int i = 0; i < count; ++i) {
            Token arg = tokens.take();
            double value = 0;
            if (arg.kind != Token::Kind::Word || !parse_number(arg.text, value)) {
                throw SceneError(arg.pos, statement.directive + " takes " + std::to_string(count) +
                                              " numbers, found " + describe(arg) +
                                              (i > 0 ? " after " + std::to_string(i) : ""));
            }
            statement.numbers.push_back(value);
        }
        if (bracketed) {
            Token close = tokens.take();
            if (close.kind != Token::Kind::Close) {
                throw SceneError(close.pos, statement.directive + " takes " + std::to_string(count) +
                                                " numbers and then ']', found " + describe(close));
            }
        }
    }

    PbrtParam read_param(Tokenizer& tokens) {
        Token declaration = tokens.take();
        PbrtParam param;
        param.pos = declaration.pos;
        std::istringstream words(declaration.text);
        std::string extra;
        words >> param.type >> param.name >> extra;
        if (param.name.empty() || !extra.empty()) {
            throw SceneError(declaration.pos, "expected a parameter declared as \"type name\", found " +
                                                  describe(declaration));
        }
        const ParamType* type = nullptr;
        for (const ParamType& t : kParamTypes) {
            if (param.type == t.name) {
                type = &t;
            }
        }
        if (!type) {
            throw SceneError(declaration.pos,
                             unknown_name_message("parameter type", param.type, param_type_names()));
        }
        // One value, or a [ ] list of them.
        std::vector<Token> values;
        if (tokens.peek().kind == Token::Kind::Open) {
            const Token open = tokens.take();
            while (tokens.peek().kind != Token::Kind::Close) {
                if (tokens.peek().kind == Token::Kind::End || tokens.peek().kind == Token::Kind::Open) {
                    throw SceneError(tokens.peek().pos, "the list of '" + param.name + "' opened at line " +
                                                            std::to_string(open.pos.line) +
                                                            " is not closed: found " +
                                                            describe(tokens.peek()));
                }
                if (values.size() >= limits_.max_list_values) {
                    throw SceneError(open.pos,
                                     "the list of '" + param.name + "' has more than " +
                                         std::to_string(limits_.max_list_values) +
                                         " values (glint's limit for a scene; large meshes belong in "
                                         "PLY files: Shape \"plymesh\")");
                }
                values.push_back(tokens.take());
            }
            tokens.take();
        } else {
            const Token& value = tokens.peek();
            if (value.kind != Token::Kind::Word && value.kind != Token::Kind::String) {
                throw SceneError(value.pos,
                                 "parameter '" + param.name + "' has no value: found " + describe(value));
            }
            values.push_back(tokens.take());
        }
        if (values.empty()) {
            throw SceneError(declaration.pos, "parameter '" + param.name + "' has an empty list of values");
        }
        store_values(param, *type, values);
        return param;
    }

    static void store_values(PbrtParam& param, const ParamType& type, const std::vector<Token>& values) {
        const bool spectrum_name =
            type.values == ParamType::Values::Spectrum && values.front().kind == Token::Kind::String;
        for (const Token& value : values) {
            if (type.values == ParamType::Values::Strings || spectrum_name) {
                if (value.kind != Token::Kind::String) {
                    throw SceneError(value.pos, "'" + param.name + "' is a " + param.type +
                                                    " parameter: expected a quoted string, found " +
                                                    describe(value));
                }
                param.strings.push_back(value.text);
            } else if (type.values == ParamType::Values::Booleans) {
                if (value.text != "true" && value.text != "false") {
                    throw SceneError(value.pos, "'" + param.name +
                                                    "' is a bool parameter: expected true or "
                                                    "false, found " +
                                                    describe(value));
                }
                param.booleans.push_back(value.text == "true");
            } else {
                double number = 0;
                if (value.kind != Token::Kind::Word || !parse_number(value.text, number)) {
                    throw SceneError(value.pos, "'" + param.name + "' is a " + param.type +
                                                    " parameter: expected a finite number, found " +
                                                    describe(value));
                }
                param.numbers.push_back(number);
            }
        }
        if (spectrum_name && param.strings.size() != 1) {
            throw SceneError(param.pos, "'" + param.name +
                                            "': a spectrum is one name (or file), or "
                                            "wavelength-value pairs");
        }
        if (!param.numbers.empty() && param.numbers.size() % static_cast<std::size_t>(type.arity) != 0) {
            throw SceneError(param.pos, "'" + param.name + "' is a " + param.type + " parameter: its " +
                                            std::to_string(param.numbers.size()) +
                                            " numbers are not a whole number of values of " +
                                            std::to_string(type.arity));
        }
    }

    void include(const PbrtStatement& statement, int depth) {
        if (depth + 1 > limits_.max_include_depth) {
            throw SceneError(statement.pos, statement.directive + " nested more than " +
                                                std::to_string(limits_.max_include_depth) +
                                                " deep (a file that includes itself?)");
        }
        const std::filesystem::path named = statement.strings.front();
        const std::filesystem::path path = named.is_relative() ? search_dir_ / named : named;
        const bool import = statement.directive == "Import";
        // An Import's graphics state stays inside its file (pbrt-v4 parses it with a copy of the state).
        PbrtStatement bracket{import ? "ImportBegin" : "", statement.pos, {}, {}, {}};
        if (import) {
            statement_(bracket);
        }
        parse_file(path, statement.pos, depth + 1);
        if (import) {
            bracket.directive = "ImportEnd";
            statement_(bracket);
        }
    }

    std::filesystem::path search_dir_;
    const std::function<void(PbrtStatement&)>& statement_;
    PbrtLimits limits_;
    std::size_t files_ = 0;
    std::size_t total_bytes_ = 0;
};

}  // namespace

void parse_pbrt_file(const std::filesystem::path& path, const std::filesystem::path& search_dir,
                     const std::function<void(PbrtStatement&)>& statement, const PbrtLimits& limits,
                     const SourcePos& mentioned_at) {
    Parser(search_dir, statement, limits).parse_file(path, mentioned_at, 0);
}

void parse_pbrt_text(const std::string& text, const std::string& display_path,
                     const std::filesystem::path& search_dir,
                     const std::function<void(PbrtStatement&)>& statement, const PbrtLimits& limits) {
    Parser(search_dir, statement, limits).parse_text(text, display_path, {}, 0);
}

}  // namespace glint
