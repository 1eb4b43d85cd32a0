// Radiance-style command-line options, each declared once (name, arguments, help, how to apply it), so
// that parsing, the usage message and `-defaults` all follow from one table.
//   -ab 5      an option with separate arguments
//   -I+ -I- -I booleans take + - 1 0 y n t f, and a bare flag toggles, as in Radiance
//   -ovd -faf  an option whose value is attached to its name
//   @file      reads more arguments from a file (whitespace-separated, # comments, quotes allowed)
//   +s         an option may be declared with a name starting with '+' (gensky +s, gendaylit +s)
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace brume {

class OptionTable {
public:
    using Apply = std::function<void(const std::vector<std::string>& args)>;

    // An option followed by `count` separate arguments.
    void add(const std::string& name, int count, const std::string& help, Apply apply,
             std::function<std::string()> current = {});
    // A boolean switch.
    void addBool(const std::string& name, bool& value, const std::string& help);
    // An option of Radiance's that Brume does not have yet: listed in the usage, refused when given, so a
    // script that depends on it fails instead of silently computing something else.
    void addUnsupported(const std::string& name, int count, const std::string& help);
    // Marks options as changing no computed value in Brume (Radiance's, kept so that its command lines run):
    // their help says so, and they are no part of valueOptions().
    void changeNothing(const std::vector<std::string>& names);
    // An option whose value is the rest of the word (-ovd, -faf); the value may be empty.
    void addAttached(const std::string& name, const std::string& help, std::function<void(const std::string&)> apply,
                     std::function<std::string()> current = {});

    // Forgets the option `name` (a program that gives a shared option another meaning declares it anew).
    void remove(const std::string& name);

    // Parses options from args[0..]; returns the index of the first non-option argument. Expands @file.
    // Throws Error on an unknown option or a missing or malformed argument.
    size_t parse(std::vector<std::string>& args) const;

    // "  -ab N    number of ambient bounces" lines, in declaration order.
    std::string usage() const;
    // The current value of every option, in Radiance's -defaults layout ("-ab 0\t\t\t\t# ambient bounces"),
    // which reads back as options (@file); an option not set (no current value) as a comment.
    std::string defaults() const;
    // "-ab 5 -aa 0.100000 ...": the options that change computed values, as they are set.
    std::vector<std::string> valueOptions() const;

private:
    enum class Kind { Separate, Bool, Attached };
    struct Option {
        std::string name;
        Kind kind;
        int count;
        std::string help;
        std::function<void(const std::vector<std::string>&)> apply;
        std::function<std::string()> current;
        bool changesValues = true;
    };
    std::string setting(const Option& o) const;
    const Option* find(const std::string& word) const;
    std::vector<Option> options_;
};

// The words of argv after the options `table` parses (and applies); a mistake in them is a UsageError that
// shows `usage` and the table's options.
std::vector<std::string> operandsAfterOptions(const OptionTable& table, int argc, char** argv, const std::string& usage);

// Options holding one number, printed by -defaults as Radiance prints them ("%f" for reals).
void addIntOption(OptionTable& table, const std::string& name, int& value, const std::string& help);
void addRealOption(OptionTable& table, const std::string& name, double& value, const std::string& help);
std::string formatReal(double value);   // "%f"
std::string formatShort(double value);  // "%g"

// Argument conversion with clear errors naming the option: "bad value 'x' for option -ab".
int toInt(const std::string& option, const std::string& text);
double toReal(const std::string& option, const std::string& text);
// Replaces @file words in args by the words in the file.
void expandResponseFiles(std::vector<std::string>& args);

}  // namespace brume
