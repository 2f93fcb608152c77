// Line-by-line reading of a BeamDyn input file, as OpenFAST's NWTC library does it: comment
// lines are skipped by position (ReadCom), a value line holds its value first and its label
// second (ReadVar), a row holds a fixed count of numbers (ReadAry). Fortran spellings are
// accepted: `1.0D-3`, `T`/`F`, `.TRUE.`, quoted strings. Every problem throws InputError
// `FILE:LINE: KEY: problem`.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace rotbeam::cases {

class DeckLines {
  public:
    // Checks the text first: at most kMaxFileBytes, no NUL or control byte except tab, CR, LF.
    DeckLines(std::string name, const std::string& text);

    const std::string& name() const { return name_; }
    int line() const { return next_; }  // 1-based number of the line read last
    int lines_left() const { return static_cast<int>(lines_.size()) - next_; }
    bool at_end() const { return lines_left() <= 0; }

    // Skips one line (a comment, a header or a blank line), which must exist.
    void comment(std::string_view what);
    // The label of the next line without consuming it ("" when none or at the end).
    std::string peek_label() const;

    // A value line: its first token, checked to carry `key` as its label (case-insensitive).
    double number(std::string_view key);
    int integer(std::string_view key, int min, int max);
    bool flag(std::string_view key);
    std::string text(std::string_view key);  // a quoted or bare string value
    // `"DEFAULT"` or a number; true when the deck gives a number (stored in `value`).
    bool number_or_default(std::string_view key, double& value);
    // A row of `count` numbers; `key` names it in messages.
    std::vector<double> row(std::string_view key, int count);

    [[noreturn]] void fail(std::string_view key, const std::string& problem) const;

  private:
    // The next line split into tokens (quoted strings are one token, without the quotes).
    std::vector<std::string> take(std::string_view key);
    std::vector<std::string> value_line(std::string_view key);
    double to_number(const std::string& token, std::string_view key) const;

    std::string name_;
    std::vector<std::string> lines_;
    int next_ = 0;
};

std::vector<std::string> split_deck_tokens(std::string_view line);

}  // namespace rotbeam::cases
