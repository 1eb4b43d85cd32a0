#include "material/bsdf_xml.h"

#include <cstdlib>
#include <map>

#include "material/xml_document.h"

namespace brume {

namespace {

// Radiance's RGB from CIE XYZ (its primaries (.640, .330), (.290, .600), (.150, .060), equal-energy white).
constexpr float kXyzToRgb[3][3] = {{2.565313f, -1.166850f, -0.398463f},
                                   {-1.022108f, 1.978287f, 0.043822f},
                                   {0.074724f, -0.251940f, 1.177215f}};

class Reader {
public:
    Reader(const std::string& shownAs, KlemsData& data) : file_(shownAs), data_(data) {}
    void read(const XmlElement& root);

private:
    [[noreturn]] void fail(const XmlElement& at, const std::string& why) const {
        throw Error(SourceLocation{file_, at.line}, why);
    }
    const XmlElement& need(const XmlElement& parent, const std::string& name) const;
    void readBases(const XmlElement& definition);
    const KlemsBasis& basis(const XmlElement& block, const std::string& which) const;
    void readBlock(const XmlElement& block, int channel, bool rowsAreIncident);
    std::vector<float> numbers(const XmlElement& data, size_t count) const;
    void addColour();

    std::string file_;
    KlemsData& data_;
    std::map<std::string, const KlemsBasis*> bases_;
    // Per distribution, the X and Z channels until colour is worked out.
    std::map<const KlemsMatrix*, std::vector<float>> x_, z_;
};

const XmlElement& Reader::need(const XmlElement& parent, const std::string& name) const {
    const XmlElement* c = parent.child(name);
    if (!c) fail(parent, "BSDF file: missing <" + name + "> in <" + parent.name + ">");
    return *c;
}

void Reader::read(const XmlElement& root) {
    if (root.name != "WindowElement") fail(root, "BSDF file: top element is <" + root.name + ">, not <WindowElement>");
    if (const XmlElement* type = root.child("FileType"); type && trimmed(type->text) != "BSDF")
        fail(*type, "BSDF file: FileType is \"" + trimmed(type->text) + "\", not BSDF");
    const XmlElement& layer = need(need(root, "Optical"), "Layer");
    const XmlElement& definition = need(layer, "DataDefinition");
    std::string structure = definition.childText("IncidentDataStructure");
    if (structure.starts_with("TensorTree"))
        fail(need(definition, "IncidentDataStructure"), "BSDF file: tensor-tree data are not supported by Brume yet");
    if (structure != "Columns" && structure != "Rows")
        fail(definition, "BSDF file: IncidentDataStructure \"" + structure + "\" is not Columns or Rows");
    readBases(definition);
    static const std::map<std::string, int> kChannels{{"Visible", 1}, {"CIE-X", 0}, {"CIE-Z", 2}};
    for (const XmlElement* w : layer.all("WavelengthData")) {
        auto channel = kChannels.find(w->childText("Wavelength"));
        if (channel == kChannels.end()) continue;  // e.g. Solar: not light
        for (const XmlElement* block : w->all("WavelengthDataBlock"))
            readBlock(*block, channel->second, structure == "Rows");
    }
    if (!data_.reflectFront && !data_.reflectBack && !data_.transmitFront && !data_.transmitBack)
        fail(layer, "BSDF file: no Visible scattering data");
    addColour();
}

// Standard bases are Radiance's own whatever the file says of them; others are read from the file.
void Reader::readBases(const XmlElement& definition) {
    for (const XmlElement* ab : definition.all("AngleBasis")) {
        std::string name = ab->childText("AngleBasisName");
        if (const KlemsBasis* b = KlemsBasis::standard(name)) {
            bases_[name] = b;
            continue;
        }
        std::vector<KlemsBasis::Ring> rings;
        for (const XmlElement* block : ab->all("AngleBasisBlock")) {
            const XmlElement& bounds = need(*block, "ThetaBounds");
            KlemsBasis::Ring r{std::atof(bounds.childText("LowerTheta").c_str()),
                               std::atof(bounds.childText("UpperTheta").c_str()),
                               std::atoi(block->childText("nPhis").c_str())};
            double expectedLower = rings.empty() ? 0.0 : rings.back().upperTheta;
            if (r.phis <= 0 || r.upperTheta <= r.lowerTheta || std::abs(r.lowerTheta - expectedLower) > 1e-6 ||
                (r.phis == 1 && r.lowerTheta > 0))
                fail(*block, "BSDF file: bad angle basis block in \"" + name + "\"");
            rings.push_back(r);
        }
        if (rings.empty() || std::abs(rings.back().upperTheta - 90) > 1e-6)
            fail(*ab, "BSDF file: angle basis \"" + name + "\" does not cover the hemisphere");
        data_.ownBases.push_back(std::make_unique<KlemsBasis>(name, rings));
        bases_[name] = data_.ownBases.back().get();
    }
}

const KlemsBasis& Reader::basis(const XmlElement& block, const std::string& which) const {
    std::string name = block.childText(which);
    auto it = bases_.find(name);
    if (it != bases_.end()) return *it->second;
    if (const KlemsBasis* b = KlemsBasis::standard(name)) return *b;
    fail(block, "BSDF file: " + which + " \"" + name + "\" is not defined");
}

void Reader::readBlock(const XmlElement& block, int channel, bool rowsAreIncident) {
    std::string direction = block.childText("WavelengthDataDirection");
    // WINDOW's front is Radiance's back.
    struct Kind {
        std::optional<KlemsMatrix> KlemsData::*slot;
        KlemsSide in, out;
    };
    static const std::map<std::string, Kind> kKinds{
        {"Transmission Front", {&KlemsData::transmitBack, {false, true}, {true, false}}},
        {"Transmission Back", {&KlemsData::transmitFront, {true, true}, {false, false}}},
        {"Reflection Front", {&KlemsData::reflectBack, {false, true}, {false, false}}},
        {"Reflection Back", {&KlemsData::reflectFront, {true, true}, {true, false}}}};
    auto kind = kKinds.find(direction);
    if (kind == kKinds.end()) fail(block, "BSDF file: unknown WavelengthDataDirection \"" + direction + "\"");
    KlemsMatrix m;
    m.in = &basis(block, "ColumnAngleBasis");
    m.out = &basis(block, "RowAngleBasis");
    m.inSide = kind->second.in;
    m.outSide = kind->second.out;
    size_t nin = size_t(m.in->size()), nout = size_t(m.out->size());
    std::vector<float> values = numbers(need(block, "ScatteringData"), nin * nout);
    if (rowsAreIncident) {  // stored [i * nout + o]
        std::vector<float> t(values.size());
        for (size_t i = 0; i < nin; ++i)
            for (size_t o = 0; o < nout; ++o) t[o * nin + i] = values[i * nout + o];
        values.swap(t);
    }
    std::optional<KlemsMatrix>& slot = data_.*(kind->second.slot);
    if (channel == 1) {
        m.y = std::move(values);
        slot = std::move(m);
        return;
    }
    // X and Z wait for the Y matrix of the same distribution (any order in the file).
    if (!slot) slot = std::move(m);
    (channel == 0 ? x_ : z_)[&*slot] = std::move(values);
}

// Whitespace- or comma-separated numbers; negative values become 0, as in Radiance.
std::vector<float> Reader::numbers(const XmlElement& data, size_t count) const {
    std::vector<float> v;
    v.reserve(count);
    const char* p = data.text.c_str();
    for (;;) {
        while (*p == ',' || std::isspace(static_cast<unsigned char>(*p))) ++p;
        if (!*p) break;
        char* end;
        double x = std::strtod(p, &end);
        if (end == p) fail(data, "BSDF file: ScatteringData holds \"" + std::string(p).substr(0, 20) + "\", not a number");
        v.push_back(float(std::max(0.0, x)));
        p = end;
    }
    if (v.size() != count)
        fail(data, "BSDF file: ScatteringData has " + std::to_string(v.size()) + " values, the bases need " +
                       std::to_string(count));
    return v;
}

void Reader::addColour() {
    for (auto* slot : {&data_.reflectFront, &data_.reflectBack, &data_.transmitFront, &data_.transmitBack}) {
        if (!*slot) continue;
        KlemsMatrix& m = **slot;
        if (m.y.empty()) {  // X or Z alone: nothing Radiance would use
            slot->reset();
            continue;
        }
        auto x = x_.find(&m), z = z_.find(&m);
        if (x == x_.end() || z == z_.end()) continue;
        m.rgb.resize(3 * m.y.size());
        for (size_t k = 0; k < m.y.size(); ++k) {
            float xyz[3] = {x->second[k], m.y[k], z->second[k]};
            for (int c = 0; c < 3; ++c)
                m.rgb[3 * k + size_t(c)] =
                    std::max(0.f, kXyzToRgb[c][0] * xyz[0] + kXyzToRgb[c][1] * xyz[1] + kXyzToRgb[c][2] * xyz[2]);
        }
    }
}

}  // namespace

KlemsData readKlemsXml(const std::string& path, const std::string& shownAs) {
    std::unique_ptr<XmlElement> root = readXmlFile(path, shownAs);
    KlemsData data;
    Reader(shownAs, data).read(*root);
    return data;
}

}  // namespace brume
