#include "fds/smv_index.h"

#include "fds/plot3d_file.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "util/error.h"

namespace brume {

namespace {

// The .smv's lines, read one by one, with their numbers for messages.
class SmvLines {
public:
    explicit SmvLines(const std::string& path) : path_(path), in_(path) {
        std::error_code ec;
        if (!in_ || std::filesystem::is_directory(path, ec)) throw Error(path + ": cannot read");
    }
    bool next(std::string& line) {
        if (!std::getline(in_, line)) return false;
        ++number_;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        return true;
    }
    // The line after a keyword, which must be there.
    std::string value(const char* what) {
        std::string line;
        if (!next(line)) fail(std::string("the file ends before ") + what);
        return line;
    }
    [[noreturn]] void fail(const std::string& what) const { throw Error(SourceLocation{path_, number_}, what); }
    int number() const { return number_; }

private:
    std::string path_;
    std::ifstream in_;
    int number_ = 0;
};

std::string trimmed(const std::string& s) {
    size_t a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
    return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

// `n` numbers from `text`, or fail naming `what`.
template <typename T>
std::vector<T> numbers(SmvLines& lines, const std::string& text, size_t n, const char* what) {
    std::istringstream in(text);
    std::vector<T> out(n);
    for (T& v : out)
        if (!(in >> v)) lines.fail(std::string("expected ") + std::to_string(n) + " numbers (" + what + ")");
    return out;
}

// TRNX/TRNY/TRNZ: a count of stretching lines to skip, then node index and coordinate for nodes 0 … cells.
std::vector<double> readNodes(SmvLines& lines, int cells, double offset, const char* what) {
    int stretching = numbers<int>(lines, lines.value(what), 1, what)[0];
    if (stretching < 0 || stretching > 1000000) lines.fail(std::string("bad count in ") + what);
    for (int i = 0; i < stretching; ++i) lines.value(what);
    std::vector<double> nodes;
    for (int i = 0; i <= cells; ++i) {
        auto v = numbers<double>(lines, lines.value(what), 2, what);
        if (int(v[0]) != i) lines.fail(std::string(what) + ": node " + std::to_string(i) + " expected");
        if (i > 0 && !(v[1] + offset > nodes.back())) lines.fail(std::string(what) + ": nodes must increase");
        nodes.push_back(v[1] + offset);
    }
    return nodes;
}

// An output file's entry after its keyword line: the file's name, then its long label, short label and units.
FdsFile readEntry(SmvLines& lines, const std::filesystem::path& dir, FdsFile f) {
    f.path = (dir / trimmed(lines.value("the file's name"))).string();
    f.quantity = trimmed(lines.value("the quantity"));
    lines.value("the short label");
    f.units = trimmed(lines.value("the units"));
    return f;
}

// "SLCC     2 # STRUCTURED %id &     0    50     0    50    21    21 !      3      1": mesh, index range.
FdsFile sliceEntry(SmvLines& lines, const std::string& line) {
    FdsFile f;
    f.kind = FdsFile::Kind::Slice;
    f.cellCentred = line.starts_with("SLCC");
    f.mesh = numbers<int>(lines, line.substr(4), 1, "the slice's mesh")[0] - 1;
    size_t amp = line.find('&');
    if (amp == std::string::npos) lines.fail("a slice entry without '&' and its index range");
    auto r = numbers<int>(lines, line.substr(amp + 1), 6, "the slice's index range");
    std::copy(r.begin(), r.end(), f.range.begin());
    return f;
}

void checkMesh(SmvLines& lines, const FdsFile& f, size_t meshes) {
    if (f.mesh < 0 || size_t(f.mesh) >= meshes) lines.fail("mesh " + std::to_string(f.mesh + 1) + " does not exist");
}

void checkRange(SmvLines& lines, const FdsFile& f, const FdsMesh& m) {
    for (int axis = 0; axis < 3; ++axis) {
        int lo = f.range[2 * axis], hi = f.range[2 * axis + 1];
        if (lo < 0 || hi < lo || hi > m.cells[axis])
            lines.fail("slice index range outside mesh " + std::to_string(f.mesh + 1));
    }
}

}  // namespace

SmvIndex readSmv(const std::string& path) {
    SmvLines lines(path);
    SmvIndex index;
    index.path = path;
    const std::filesystem::path dir = std::filesystem::path(path).parent_path();
    int declared = -1;
    glm::dvec3 offset(0);
    std::string line;
    auto mesh = [&]() -> FdsMesh& {
        if (index.meshes.empty()) lines.fail("mesh data before the first GRID");
        return index.meshes.back();
    };
    while (lines.next(line)) {
        std::string key = line.substr(0, line.find_first_of(" \t"));
        if (key == "CHID") index.chid = trimmed(lines.value("CHID"));
        else if (key == "NMESHES") declared = numbers<int>(lines, lines.value("NMESHES"), 1, "NMESHES")[0];
        else if (key == "OFFSET") {
            auto v = numbers<double>(lines, lines.value("OFFSET"), 3, "OFFSET");
            offset = {v[0], v[1], v[2]};
        } else if (key == "GRID") {
            FdsMesh m;
            m.id = trimmed(line.substr(4));
            auto c = numbers<int>(lines, lines.value("GRID"), 3, "IBAR JBAR KBAR");
            m.cells = {c[0], c[1], c[2]};
            if (m.cells.x < 1 || m.cells.y < 1 || m.cells.z < 1 || double(c[0]) * c[1] * c[2] > 1e10)
                lines.fail("bad cell counts");
            index.meshes.push_back(m);
        } else if (key == "TRNX" || key == "TRNY" || key == "TRNZ") {
            int axis = key[3] - 'X';
            FdsMesh& m = mesh();
            m.nodes[axis] = readNodes(lines, m.cells[axis], offset[axis], key.c_str());
        } else if (key == "SMOKF3D" || key == "SMOKG3D" || key == "SMOKE3D") {
            FdsFile f;
            f.kind = FdsFile::Kind::Smoke3d;
            f.line = lines.number();
            // Mesh, then (since FDS 6) the mass extinction coefficient the bytes were encoded with.
            std::istringstream in(line.substr(7));
            if (!(in >> f.mesh)) lines.fail("expected the 3D smoke file's mesh");
            --f.mesh;
            if (!(in >> f.massExtinction)) f.massExtinction = 0;
            checkMesh(lines, f, index.meshes.size());
            index.files.push_back(readEntry(lines, dir, f));
        } else if (key == "PL3D") {
            // "PL3D time mesh", the file, then five quantities of three lines each (label, short label, units).
            FdsFile f;
            f.kind = FdsFile::Kind::Plot3d;
            f.line = lines.number();
            f.mesh = numbers<double>(lines, line.substr(4), 2, "the Plot3D file's time and mesh")[1] - 1;
            checkMesh(lines, f, index.meshes.size());
            f.path = (dir / trimmed(lines.value("the file's name"))).string();
            std::optional<double> time = plot3dTime(f.path);
            if (!time) lines.fail("the Plot3D file's name does not give its time (..._5p03.q)");
            f.time = *time;
            for (int k = 0; k < 5; ++k) {
                FdsFile q = f;
                q.block = k;
                q.quantity = trimmed(lines.value("a Plot3D quantity"));
                lines.value("its short label");
                q.units = trimmed(lines.value("its units"));
                index.files.push_back(q);
            }
        } else if (key == "SLCF" || key == "SLCC") {
            FdsFile f = sliceEntry(lines, line);
            f.line = lines.number();
            checkMesh(lines, f, index.meshes.size());
            checkRange(lines, f, index.meshes[f.mesh]);
            index.files.push_back(readEntry(lines, dir, f));
        }
    }
    if (index.meshes.empty()) lines.fail("no GRID: not an FDS .smv file");
    if (declared >= 0 && size_t(declared) != index.meshes.size())
        lines.fail("NMESHES says " + std::to_string(declared) + " but " + std::to_string(index.meshes.size()) +
                   " meshes are listed");
    for (size_t i = 0; i < index.meshes.size(); ++i)
        for (int axis = 0; axis < 3; ++axis)
            if (index.meshes[i].nodes[axis].empty())
                lines.fail("mesh " + std::to_string(i + 1) + " has no TRN" + char('X' + axis) + " nodes");
    return index;
}

}  // namespace brume
