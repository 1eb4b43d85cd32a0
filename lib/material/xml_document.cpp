#include "material/xml_document.h"

#include <expat.h>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace brume {

namespace {

struct Builder {
    XML_Parser parser;
    int skippedLines = 0;  // lines before the document's first '<', which the parser does not see
    std::unique_ptr<XmlElement> root;
    std::vector<XmlElement*> open;
};

void XMLCALL startElement(void* data, const XML_Char* name, const XML_Char**) {
    auto* b = static_cast<Builder*>(data);
    auto e = std::make_unique<XmlElement>();
    e->name = name;
    e->line = int(XML_GetCurrentLineNumber(b->parser)) + b->skippedLines;
    XmlElement* raw = e.get();
    if (b->open.empty()) b->root = std::move(e);
    else b->open.back()->children.push_back(std::move(e));
    b->open.push_back(raw);
}

void XMLCALL endElement(void* data, const XML_Char*) { static_cast<Builder*>(data)->open.pop_back(); }

void XMLCALL characters(void* data, const XML_Char* s, int len) {
    auto* b = static_cast<Builder*>(data);
    if (!b->open.empty()) b->open.back()->text.append(s, size_t(len));
}

}  // namespace

const XmlElement* XmlElement::child(const std::string& n) const {
    for (const auto& c : children)
        if (c->name == n) return c.get();
    return nullptr;
}

std::vector<const XmlElement*> XmlElement::all(const std::string& n) const {
    std::vector<const XmlElement*> found;
    for (const auto& c : children)
        if (c->name == n) found.push_back(c.get());
    return found;
}

std::string XmlElement::childText(const std::string& n) const {
    const XmlElement* c = child(n);
    return c ? trimmed(c->text) : std::string();
}

std::string trimmed(const std::string& s) {
    size_t a = s.find_first_not_of(" \t\r\n"), b = s.find_last_not_of(" \t\r\n");
    return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

std::unique_ptr<XmlElement> readXmlFile(const std::string& path, const std::string& shownAs) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("cannot open XML file \"" + shownAs + "\"");
    std::stringstream text;
    text << in.rdbuf();
    std::string s = text.str();
    Builder b;
    // Text before the first '<' is skipped, as Radiance's XML reader skips it: genBSDF's files can begin with its
    // "Recover using: genBSDF -recover …" line (the LBNL tutorials' blinds.xml does).
    size_t start = std::min(s.find('<'), s.size());
    b.skippedLines = int(std::count(s.begin(), s.begin() + std::ptrdiff_t(start), '\n'));
    s.erase(0, start);
    b.parser = XML_ParserCreate(nullptr);
    XML_SetUserData(b.parser, &b);
    XML_SetElementHandler(b.parser, startElement, endElement);
    XML_SetCharacterDataHandler(b.parser, characters);
    bool ok = XML_Parse(b.parser, s.data(), int(s.size()), 1) == XML_STATUS_OK;
    int line = int(XML_GetCurrentLineNumber(b.parser)) + b.skippedLines;
    std::string why = ok ? "" : XML_ErrorString(XML_GetErrorCode(b.parser));
    XML_ParserFree(b.parser);
    if (!ok) throw Error(SourceLocation{shownAs, line}, "malformed XML: " + why);
    return std::move(b.root);
}

}  // namespace brume
