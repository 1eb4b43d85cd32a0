#include "material/bsdf_xml.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "scene_text.h"
#include "util/error.h"

namespace brume {
namespace {

using test::errorOf;

const std::string kFile = std::string(BRUME_TEST_DATA) + "/bsdf/prism_quarter.xml";

TEST(BsdfXml, ReadsTheFourKlemsMatricesInRadiancesOrientation) {
    KlemsData d = readKlemsXml(kFile, kFile);
    ASSERT_TRUE(d.reflectFront && d.reflectBack && d.transmitFront && d.transmitBack);
    const KlemsMatrix& r = *d.reflectFront;  // the file's "Reflection Back"
    EXPECT_EQ(r.in->name(), "LBNL/Klems Quarter");
    EXPECT_EQ(r.y.size(), 41u * 41u);
    EXPECT_TRUE(r.rgb.empty());
    // "Columns": each line is one outgoing patch across the incident ones.
    EXPECT_FLOAT_EQ(r.value(0, 0), 0.46836f);
    EXPECT_FLOAT_EQ(r.value(0, 1), 0.137318f);
    EXPECT_FLOAT_EQ(r.value(1, 0), 0.132793f);
    EXPECT_TRUE(r.inSide.front && r.inSide.incident && r.outSide.front && !r.outSide.incident);
    EXPECT_TRUE(d.transmitBack->inSide.incident && !d.transmitBack->inSide.front && d.transmitBack->outSide.front);
}

class BsdfXmlText : public ::testing::Test {
protected:
    // One file per test and process: ctest runs this fixture's tests at once.
    std::string path = (std::filesystem::temp_directory_path() /
                        ("brume_bsdf_xml_" + std::to_string(::getpid()) + "_" +
                         ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".xml"))
                           .string();
    void TearDown() override { std::filesystem::remove(path); }

    // A file with one distribution on a basis of 3 patches (a polar cap, two below it); `blocks` go first,
    // `before` before the document.
    KlemsData read(const std::string& data, const std::string& structure = "Columns",
                   const std::string& blocks = "", const std::string& before = "") {
        std::ofstream(path) << before << "<?xml version=\"1.0\"?>\n<WindowElement>\n<FileType>BSDF</FileType>\n<Optical><Layer>\n"
                               "<DataDefinition><IncidentDataStructure>"
                            << structure
                            << "</IncidentDataStructure>\n<AngleBasis><AngleBasisName>Two</AngleBasisName>\n"
                               "<AngleBasisBlock><nPhis>1</nPhis><ThetaBounds><LowerTheta>0</LowerTheta>"
                               "<UpperTheta>45</UpperTheta></ThetaBounds></AngleBasisBlock>\n"
                               "<AngleBasisBlock><nPhis>2</nPhis><ThetaBounds><LowerTheta>45</LowerTheta>"
                               "<UpperTheta>90</UpperTheta></ThetaBounds></AngleBasisBlock>\n"
                               "</AngleBasis></DataDefinition>\n"
                            << blocks << block("Visible", data) << "</Layer></Optical></WindowElement>\n";
        return readKlemsXml(path, "w.xml");
    }
    static std::string block(const std::string& wavelength, const std::string& data) {
        return "<WavelengthData><Wavelength>" + wavelength +
               "</Wavelength><WavelengthDataBlock>\n<WavelengthDataDirection>Transmission Front"
               "</WavelengthDataDirection><ColumnAngleBasis>Two</ColumnAngleBasis><RowAngleBasis>Two"
               "</RowAngleBasis>\n<ScatteringData>" +
               data + "</ScatteringData></WavelengthDataBlock></WavelengthData>\n";
    }
};

TEST_F(BsdfXmlText, OwnBasesRowsAndCommas) {
    KlemsData d = read("1, 2, 3, 4,5,6 7 8 9", "Rows");
    ASSERT_TRUE(d.transmitBack && !d.transmitFront);
    EXPECT_EQ(d.transmitBack->in->size(), 3);
    EXPECT_FLOAT_EQ(d.transmitBack->value(1, 0), 2);  // rows are incident patches
    EXPECT_FLOAT_EQ(d.transmitBack->value(0, 1), 4);
}

TEST_F(BsdfXmlText, SolarIsSkippedAndXyzGivesColour) {
    const std::string kOnes = "1 1 1 1 1 1 1 1 1";
    KlemsData d = read(kOnes, "Columns", block("Solar", "9 9 9 9 9 9 9 9 9") + block("CIE-X", kOnes) +
                                           block("CIE-Z", kOnes));
    ASSERT_EQ(d.transmitBack->rgb.size(), 27u);
    EXPECT_FLOAT_EQ(d.transmitBack->value(0, 0), 1);
    // Equal-energy white stays white in Radiance's RGB.
    EXPECT_NEAR(d.transmitBack->rgb[0], 1, 1e-4);
    EXPECT_NEAR(d.transmitBack->rgb[1], 1, 1e-4);
    EXPECT_NEAR(d.transmitBack->rgb[2], 1, 1e-4);
}

// genBSDF's files may begin with its "Recover using" line (the LBNL tutorials' blinds.xml): skipped, as Radiance's
// reader skips text before the first '<', and the lines still counted.
TEST_F(BsdfXmlText, TextBeforeTheDocumentIsSkipped) {
    const std::string recover = "Recover using: /usr/local/bin/genBSDF -recover /tmp/genBSDF.xMTbXO\n";
    KlemsData d = read("1 2 3 4 5 6 7 8 9", "Columns", "", recover);
    ASSERT_TRUE(d.transmitBack);
    EXPECT_FLOAT_EQ(d.transmitBack->value(0, 1), 2);
    EXPECT_EQ(errorOf([&] { read("1 2 3", "Columns", "", recover); }),
              "w.xml:13: BSDF file: ScatteringData has 3 values, the bases need 9");
}

TEST_F(BsdfXmlText, BadFilesSayWhereAndWhat) {
    EXPECT_EQ(errorOf([&] { read("1 2 3"); }), "w.xml:12: BSDF file: ScatteringData has 3 values, the bases need 9");
    EXPECT_EQ(errorOf([&] { read("1 2 x 4 5 6 7 8 9"); }), "w.xml:12: BSDF file: ScatteringData holds \"x 4 5 6 7 8 9\", not a number");
    EXPECT_EQ(errorOf([&] { read("1", "TensorTree3"); }),
              "w.xml:5: BSDF file: tensor-tree data are not supported by Brume yet");
    EXPECT_EQ(errorOf([&] { read("1</Oops>"); }).substr(0, 22), "w.xml:12: malformed XM");
    EXPECT_EQ(errorOf([&] { readKlemsXml("/nonexistent.xml", "n.xml"); }), "cannot open XML file \"n.xml\"");
}

}  // namespace
}  // namespace brume
