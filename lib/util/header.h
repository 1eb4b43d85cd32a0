// Radiance data-stream headers: "#?RADIANCE", the command that made the stream, SOFTWARE=, dates,
// FORMAT=, ended by an empty line.
#pragma once
#include <string>
#include <vector>

namespace brume {

// The command line as Radiance prints it in headers: words joined by spaces, quoted where needed.
std::string commandLine(const std::vector<std::string>& words);
// "SOFTWARE= Brume x.y", "CAPDATE= ...", "GMT= ..." lines.
std::string softwareAndDates();

}  // namespace brume
