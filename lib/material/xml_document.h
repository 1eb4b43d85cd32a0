// A small read-only XML tree with the line each element starts on, so that readers of XML data files
// (LBNL/WINDOW BSDFs) can report "file:line: message". Parsed by expat; namespaces are not resolved
// (WINDOW files use one default namespace and unprefixed names).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "util/error.h"

namespace brume {

struct XmlElement {
    std::string name;
    std::string text;  // character data directly inside, concatenated
    int line = 0;
    std::vector<std::unique_ptr<XmlElement>> children;

    // The first child named `name`, or nullptr.
    const XmlElement* child(const std::string& name) const;
    std::vector<const XmlElement*> all(const std::string& name) const;
    // The text of child `name` with surrounding white space removed ("" when absent).
    std::string childText(const std::string& name) const;
};

// Parses file `path` (named `shownAs` in messages). Throws Error "file:line: ..." on malformed XML or
// when the file cannot be read.
std::unique_ptr<XmlElement> readXmlFile(const std::string& path, const std::string& shownAs);

std::string trimmed(const std::string& s);

}  // namespace brume
