// Radiance data-stream headers: "#?RADIANCE", the command that made the stream, SOFTWARE=, dates,
// FORMAT=, ended by an empty line.
#pragma once
#include <string>
#include <vector>

namespace brume {

// A word as Radiance's fputword writes it (in headers and scene text): quoted when empty or holding white
// space or an inner quote, with the other kind of quote.
std::string quotedWord(const std::string& word);
// The command line as Radiance prints it in headers: words joined by spaces, quoted where needed.
std::string commandLine(const std::vector<std::string>& words);
// "SOFTWARE= Brume x.y", "CAPDATE= ...", "GMT= ..." lines.
std::string softwareAndDates();

}  // namespace brume
