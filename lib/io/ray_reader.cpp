#include "io/ray_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string_view>

#include <glm/geometric.hpp>

#include "util/error.h"

namespace brume {

namespace {

constexpr size_t kLongestWord = RayReader::kLongestWord;

bool isBlank(int c) { return c != '\n' && c != EOF && std::isspace(c); }

// Radiance's isflt (common/words.c), the words its rtrace takes as numbers: an optional sign, digits with
// at most one point among them, an optional exponent of at least one digit. No hexadecimal, inf or nan.
// `w` is followed by a NUL.
bool isDecimal(std::string_view w) {
    const char* s = w.data();
    if (*s == '-' || *s == '+') ++s;
    const char* digits = s;
    while (std::isdigit(static_cast<unsigned char>(*s))) ++s;
    bool any = s > digits;
    if (*s == '.') {
        ++s;
        any = any || std::isdigit(static_cast<unsigned char>(*s));
        while (std::isdigit(static_cast<unsigned char>(*s))) ++s;
    }
    if (!any) return false;
    if (*s == 'e' || *s == 'E') {
        ++s;
        if (*s == '-' || *s == '+') ++s;
        if (!std::isdigit(static_cast<unsigned char>(*s))) return false;
        while (std::isdigit(static_cast<unsigned char>(*s))) ++s;
    }
    return s == w.data() + w.size();  // not at a NUL byte inside the word
}

// `w` in double quotes for a message (shownBytes: binary input read as ASCII never reaches the terminal).
std::string quoted(std::string_view w) { return "\"" + shownBytes(w, kLongestWord) + "\""; }

}  // namespace

bool RayReader::next(std::array<double, 6>& ray) {
    return format_ == 'a' ? nextLine(ray) : nextRecord(ray);
}

// Reads one word into word_ (up to one character past kLongestWord), `c` being its first character, read
// straight from the stream buffer: rays come by the million, and formatted extraction costs more than
// tracing them. Returns the character after the word, not taken.
int RayReader::word(int c) {
    std::streambuf* buf = in_.rdbuf();
    wordLength_ = 0;
    for (; c != EOF && !std::isspace(c); c = buf->snextc())
        if (wordLength_ <= kLongestWord) word_[wordLength_++] = char(c);
    word_[wordLength_] = '\0';
    return c;
}

// word_ as a number; an Error naming the line if it is not one, or not a finite one.
double RayReader::number() const {
    std::string_view w(word_.data(), wordLength_);
    if (w.size() > kLongestWord)
        throw lineError(quoted(w) + " is too long for a number (more than " + std::to_string(kLongestWord) +
                        " characters)");
    char* end = nullptr;
    double v = std::strtod(w.data(), &end);
    if (isDecimal(w) && std::isfinite(v)) return v;
    if (end == w.data() + w.size() && !std::isfinite(v)) throw lineError(quoted(w) + " is not a finite number");
    if (w.find(',') != std::string_view::npos)
        throw lineError(quoted(w) + " is not a number: fields are separated by white space, not commas");
    throw lineError(quoted(w) + " is not a number (a ray is six numbers: origin and direction)");
}

// "(stdin):LINE: what" for the line being read (counted in a long: grid files of billions of rays exist).
Error RayReader::lineError(const std::string& what) const {
    return Error(name_ + ":" + std::to_string(lines_ + 1) + ": " + what);
}

bool RayReader::nextLine(std::array<double, 6>& ray) {
    std::streambuf* buf = in_.rdbuf();
    int c = buf->sgetc();
    for (;; c = buf->snextc(), ++lines_) {  // blank lines
        while (isBlank(c)) c = buf->snextc();
        if (c != '\n') break;
    }
    if (c == EOF) return false;
    int count = 0;
    while (c != '\n' && c != EOF) {
        c = word(c);
        double v = number();
        if (count < 6) ray[count] = v;
        ++count;
        while (isBlank(c)) c = buf->snextc();
    }
    // The newline is taken without looking past it: on a pipe the next line may not be written yet, and
    // the program driving rtrace waits for this ray's answer before writing it.
    if (c == '\n') buf->sbumpc();
    if (count != 6) throw lineError(std::to_string(count) + (count == 1 ? " number" : " numbers") + ", a ray needs 6");
    ++lines_;
    return true;
}

// "(stdin): ray N: what" for the record being read, counted from 1.
Error RayReader::recordError(const std::string& what) const {
    return Error(name_ + ": ray " + std::to_string(records_) + ": " + what);
}

bool RayReader::nextRecord(std::array<double, 6>& ray) {
    const size_t size = format_ == 'f' ? sizeof(float) : sizeof(double);
    char bytes[6 * sizeof(double)];
    in_.read(bytes, std::streamsize(6 * size));
    size_t got = size_t(in_.gcount());
    if (got == 0) return false;
    ++records_;
    if (got < 6 * size)
        throw recordError("partial record, " + std::to_string(got) + " of " + std::to_string(6 * size) + " bytes");
    for (int i = 0; i < 6; ++i) {
        if (size == sizeof(float)) {
            float f;
            std::memcpy(&f, bytes + i * size, size);
            ray[i] = f;
        } else {
            std::memcpy(&ray[i], bytes + i * size, size);
        }
        if (!std::isfinite(ray[i]))
            throw recordError("number " + std::to_string(i + 1) + " of 6 is " + (std::isnan(ray[i]) ? "NaN" : "infinite") +
                              ", not a finite number");
    }
    return true;
}

InputRay inputRay(const std::array<double, 6>& r) {
    dvec3 org(r[0], r[1], r[2]), dir(r[3], r[4], r[5]);
    // Scaled by its largest component first: the squares of components beyond 1e154 overflow, those of
    // components below 1e-154 vanish.
    double largest = std::max({std::abs(dir.x), std::abs(dir.y), std::abs(dir.z)});
    if (largest == 0) return {org, dir, 0, true};
    dvec3 scaled = dir / largest;
    double length = glm::length(scaled);
    return {org, scaled / length, largest * length, false};
}

bool RayBatches::read(std::array<double, 6>& ray) {
    try {
        return reader_.next(ray);
    } catch (const Error&) {
        error_ = std::current_exception();
        return false;
    }
}

bool RayBatches::next(std::vector<InputRay>& rays) {
    if (error_) std::rethrow_exception(error_);
    first_ = uint64_t(count_);
    rays.clear();
    std::array<double, 6> r;
    while (!done_ && rays.size() < size_) {
        if (limit_ > 0 && count_ >= limit_) {
            done_ = true;
            break;
        }
        if (!read(r)) {
            done_ = true;
            if (limit_ > 0 && !error_) warn("unexpected EOF on input");
            break;
        }
        ++count_;
        rays.push_back(inputRay(r));
        if (rays.back().zero) break;  // a flush request: finish what came before it
    }
    if (rays.empty() && error_) std::rethrow_exception(error_);
    return !rays.empty();
}

}  // namespace brume
