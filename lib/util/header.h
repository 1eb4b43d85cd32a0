// Radiance data-stream headers: "#?RADIANCE", the command that made the stream, SOFTWARE=, dates,
// FORMAT=, ended by an empty line.
#pragma once
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

namespace brume {

// A word as Radiance's fputword writes it (in headers and scene text): quoted when empty or holding white
// space or an inner quote, with the other kind of quote.
std::string quotedWord(const std::string& word);
// The command line as Radiance prints it in headers: words joined by spaces, quoted where needed.
std::string commandLine(const std::vector<std::string>& words);
// "SOFTWARE= Brume x.y", "CAPDATE= ...", "GMT= ..." lines.
std::string softwareAndDates();

// Ends `header` as Radiance ends a data stream's header: "FORMAT=format", padded with spaces after binary
// floats or doubles so that the data start aligned in a file (`out`'s position tells where the header
// starts; a pipe has none, and gets no padding), and the empty line.
void endHeader(std::string& header, const std::string& format, std::FILE* out);

// Whether a header line sets the variable `name` (given with its '=', as "VIEW="), by Radiance's prefix rule.
bool isHeaderVariable(std::string_view line, std::string_view name);
// The product of the values of every line setting `name`: Radiance multiplies EXPOSURE= and PIXASPECT=
// lines (pfilt after rpict adds one more); 1 without any.
double headerProduct(const std::vector<std::string>& lines, std::string_view name);

}  // namespace brume
