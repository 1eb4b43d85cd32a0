#include "contrib/contribution_output.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <map>
#include <sys/stat.h>
#include <unistd.h>

#include "io/value_writer.h"
#include "spectrum/spectrum.h"
#include "util/error.h"
#include "util/header.h"

namespace brume {

std::string outputName(const std::string& pattern, const std::string& name, int bin) {
    std::string out;
    for (size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '%') {
            out += pattern[i];
            continue;
        }
        size_t j = i + 1;
        while (j < pattern.size() && (std::isdigit(static_cast<unsigned char>(pattern[j])) || pattern[j] == '-'))
            ++j;
        if (j == pattern.size()) throw Error("-o " + pattern + ": a '%' ends the pattern");
        std::string flags = pattern.substr(i + 1, j - i - 1);
        char buffer[64];
        if (pattern[j] == '%' && flags.empty()) out += '%';
        else if (pattern[j] == 's' && flags.empty()) out += name;
        else if (pattern[j] == 'd' && flags.size() < 8) {
            std::snprintf(buffer, sizeof buffer, ("%" + flags + "d").c_str(), bin);
            out += buffer;
        } else {
            throw Error("-o " + pattern + ": only %s (the modifier), %d (the bin) and %% may be used");
        }
        i = j;
    }
    return out;
}

namespace {

bool exists(const std::string& path) {
    struct stat st;
    return ::stat(path.c_str(), &st) == 0;
}

const char* formatWord(char format, int channels) {
    if (format == 'c') return channels > 3 ? "Radiance_spectra" : "32-bit_rle_rgbe";
    return format == 'f' ? "float" : format == 'd' ? "double" : "ascii";
}

}  // namespace

ContributionOutput::ContributionOutput(const ModifierBins& bins, const OutputSettings& settings) : settings_(settings) {
    // Streams by name ("" the standard output), in the order of their first columns.
    std::map<std::string, size_t> byName;
    for (const ModifierBins::Tallied& m : bins.modifiers()) {
        if (!m.output.empty() && m.output[0] == '!')
            throw Error("-o " + m.output + ": commands as outputs are not supported");
        for (int b = 0; b < m.bins; ++b) {
            std::string name = m.output.empty() ? "" : outputName(m.output, m.name, b);
            auto [it, added] = byName.emplace(name, streams_.size());
            if (added) streams_.push_back(Stream{name, {}, name.empty() ? stdout : nullptr, {}, m.name, b});
            Stream& s = streams_[it->second];
            s.columns.push_back(m.column + b);
            if (s.modifier != m.name) s.modifier.clear();
        }
    }
    for (Stream& s : streams_)
        if (!s.name.empty() && exists(s.name) && !settings.overwrite) throw Error(s.name + ": exists (-fo to overwrite it)");
    for (Stream& s : streams_) {
        if (s.name.empty()) continue;
        s.partial = s.name + ".partial" + std::to_string(::getpid());
        s.file = std::fopen(s.partial.c_str(), "wb");
        if (!s.file) throw Error(s.name + ": cannot write: " + std::strerror(errno));
    }
    if (settings.header)
        for (Stream& s : streams_) writeHeader(s);
}

ContributionOutput::~ContributionOutput() {
    if (finished_) return;
    for (Stream& s : streams_) {
        if (s.file == stdout || !s.file) continue;
        std::fclose(s.file);
        std::remove(s.partial.c_str());
    }
}

// NCOMP, then the modifier and bin where the stream holds one, NROWS, NCOLS, FORMAT.
void ContributionOutput::writeHeader(Stream& s) const {
    std::string h = "#?RADIANCE\n";
    for (const std::string& line : settings_.headerLines) h += line + "\n";
    h += softwareAndDates();
    h += "NCOMP=" + std::to_string(settings_.channels) + "\n";
    for (const std::string& line : settings_.colorLines) h += line + "\n";
    if (!s.name.empty() && !s.modifier.empty()) {
        h += "MODIFIER=" + s.modifier + "\n";
        if (s.columns.size() == 1) h += "BIN=" + std::to_string(s.bin) + "\n";
    }
    if (settings_.yres > 0) h += "NROWS=" + std::to_string(settings_.yres * std::max(settings_.xres, 1)) + "\n";
    bool picture = settings_.xres > 0 && settings_.yres > 0 && s.columns.size() == 1;
    if (!picture) h += "NCOLS=" + std::to_string(s.columns.size()) + "\n";
    if (settings_.format == 'f' || settings_.format == 'd')
        h += std::string("BigEndian=") + (std::endian::native == std::endian::big ? "1" : "0") + "\n";
    endHeader(h, formatWord(settings_.format, settings_.channels), s.file);
    if (picture) {
        char resolution[64];
        std::snprintf(resolution, sizeof resolution, "-Y %8d +X %8d\n", settings_.yres, settings_.xres);
        h += resolution;
    }
    std::fputs(h.c_str(), s.file);
}

void ContributionOutput::write(const std::vector<double>& record) {
    const int n = settings_.channels;
    for (Stream& s : streams_) {
        for (int c : s.columns) {
            const double* v = &record[size_t(c) * n];
            for (int k = 0; k < n; ++k) {
                if (settings_.format == 'a') {
                    std::fprintf(s.file, "%e\t", v[k]);
                } else if (settings_.format == 'f') {
                    float f = float(v[k]);
                    std::fwrite(&f, sizeof f, 1, s.file);
                } else if (settings_.format == 'd') {
                    std::fwrite(&v[k], sizeof(double), 1, s.file);
                }
            }
            if (settings_.format == 'c') {
                unsigned char bytes[Spectrum::kMaxChannels + 1];
                if (n == 3) encodeRgbe(float(v[0]), float(v[1]), float(v[2]), bytes);
                else encodeCommonExponent(v, n, bytes);
                std::fwrite(bytes, 1, size_t(n == 3 ? 4 : n + 1), s.file);
            }
        }
        if (settings_.format == 'a') std::fputc('\n', s.file);
        if (std::ferror(s.file)) throw Error((s.name.empty() ? std::string("(stdout)") : s.name) + ": write error");
    }
}

void ContributionOutput::flush() {
    for (Stream& s : streams_) std::fflush(s.file);
}

void ContributionOutput::finish() {
    for (Stream& s : streams_) {
        if (s.file == stdout) {
            if (std::fflush(stdout) != 0) throw Error("(stdout): write error");
            continue;
        }
        bool failed = std::fclose(s.file) != 0;
        s.file = nullptr;
        if (failed || std::rename(s.partial.c_str(), s.name.c_str()) != 0) {
            std::remove(s.partial.c_str());
            throw Error(s.name + ": cannot write: " + std::strerror(errno));
        }
    }
    finished_ = true;
}

}  // namespace brume
