// The prescription file: the shared tables' four columns, the optional V_d column and keyed
// asphere fields, and errors that name the file, the line and the field.
#include "obscura/camera/lens_prescription_file.h"

#include <gtest/gtest.h>

#include <string>

#include "obscura/math/error.h"

namespace obscura {
namespace {

// The message of the obscura::Error that parsing `text` throws ("" when it parses).
std::string error_of(const std::string& text) {
  try {
    parse_lens_prescription(text, "lens.tsv", "test");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(LensPrescriptionFile, ReadsColumnsCommentsAbbeNumbersAndAspheres) {
  LensPrescription p = parse_lens_prescription(
      "# a comment line\n"
      "\n"
      "40\t5\t1.5168\t20\t64.17   # N-BK7\n"
      "-40 2 1 20 conic=-1.5 A4=1e-5 A16=-2e-20\n"
      "0\t10\t0\t12\n"
      "+80 4 1.6 22 V_d=40\n"
      "-200 0 1 22\n",
      "lens.tsv", "test");
  ASSERT_EQ(p.surfaces.size(), 5u);
  EXPECT_EQ(p.name, "test");
  EXPECT_EQ(p.surfaces[0].radius_mm, 40);
  EXPECT_EQ(p.surfaces[0].n_d, 1.5168);
  EXPECT_EQ(p.surfaces[0].abbe_number, 64.17);
  EXPECT_EQ(p.surfaces[1].conic, -1.5);
  EXPECT_EQ(p.surfaces[1].aspheric[0], 1e-5);
  EXPECT_EQ(p.surfaces[1].aspheric[6], -2e-20);
  EXPECT_TRUE(p.surfaces[2].is_stop);
  EXPECT_EQ(p.surfaces[2].n_d, 1);  // the stop's "0" is air
  EXPECT_EQ(p.surfaces[3].radius_mm, 80);
  EXPECT_EQ(p.surfaces[3].abbe_number, 40);
}

TEST(LensPrescriptionFile, BadNumberNamesLineAndField) {
  std::string e = error_of("40 5 1.5 20\n0 1 0 10\n-40 0 1.5x 20\n");
  EXPECT_NE(e.find("lens.tsv:3"), std::string::npos) << e;
  EXPECT_NE(e.find("n_d"), std::string::npos) << e;
  EXPECT_NE(e.find("1.5x"), std::string::npos) << e;
  e = error_of("40 5 1.5 20\n0 1 0 10\n-40 0 1 20 A5=3\n");
  EXPECT_NE(e.find("lens.tsv:3"), std::string::npos) << e;
  EXPECT_NE(e.find("A5"), std::string::npos) << e;
  e = error_of("40 5 1.5 nan\n0 1 0 10\n-40 0 1 20\n");
  EXPECT_NE(e.find("lens.tsv:1"), std::string::npos) << e;
  EXPECT_NE(e.find("aperture_diameter_mm"), std::string::npos) << e;
}

TEST(LensPrescriptionFile, WrongColumnCountNamesLine) {
  std::string e = error_of("40 5 1.5 20\n0 1 0\n-40 0 1 20\n");
  EXPECT_NE(e.find("lens.tsv:2"), std::string::npos) << e;
  EXPECT_NE(e.find("expected 4 numbers"), std::string::npos) << e;
  e = error_of("40 5 1.5 20 60 7\n0 1 0 10\n-40 0 1 20\n");
  EXPECT_NE(e.find("lens.tsv:1"), std::string::npos) << e;
}

TEST(LensPrescriptionFile, MissingOrDoubledStopAndBadValuesAreErrors) {
  std::string e = error_of("40 5 1.5 20\n-40 0 1 20\n");
  EXPECT_NE(e.find("lens.tsv"), std::string::npos) << e;
  EXPECT_NE(e.find("no aperture stop"), std::string::npos) << e;
  e = error_of("0 1 0 10\n40 5 1.5 20\n0 1 0 10\n-40 0 1 20\n");
  EXPECT_NE(e.find("lens.tsv:3"), std::string::npos) << e;
  EXPECT_NE(e.find("second aperture stop"), std::string::npos) << e;
  e = error_of("40 5 1.5 20\n12 1 0 10\n-40 0 1 20\n");  // a curved stop
  EXPECT_NE(e.find("lens.tsv:2"), std::string::npos) << e;
  e = error_of("40 -5 1.5 20\n0 1 0 10\n-40 0 1 20\n");
  EXPECT_NE(e.find("thickness_mm"), std::string::npos) << e;
  e = error_of("40 5 0.8 20\n0 1 0 10\n-40 0 1 20\n");
  EXPECT_NE(e.find("n_d"), std::string::npos) << e;
  e = error_of("40 5 1.5 20\n0 1 0 10\n-40 0 1.5 20\n");  // glass towards the sensor
  EXPECT_NE(e.find("lens.tsv:3"), std::string::npos) << e;
  EXPECT_NE(error_of("# nothing\n").find("no surfaces"), std::string::npos);
}

TEST(LensPrescriptionFile, UnreadableFileIsAnError) {
  EXPECT_THROW(load_lens_prescription("/nonexistent/lens.tsv"), Error);
}

}  // namespace
}  // namespace obscura
