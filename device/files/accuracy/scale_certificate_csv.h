#pragma once
// A glass line scale's calibration certificate as CSV: schema
// "benchpilot.scale-certificate", version 1 (docs/accuracy.md, "Scale certificate"):
//
//   # benchpilot.scale-certificate 1
//   # scale: free text (the scale, its serial, the laboratory)
//   graduation_mm,deviation_um
//   0,0
//   10,0.21
//
// The first line names the schema and version; other lines starting with '#' are notes.
// graduation may be given in another length unit by its column name's suffix (_mm,
// _um, …), deviation likewise (_um, _nm, _mm). Graduations increase, lie on the scale's
// pitch and within its length; anything else is a certificate of another scale and is
// refused with the file, line and column of the cell at fault. Plain C++ (the fuzzer).
#include "device/files/accuracy/file_problem.h"
#include "motion/checked.h"
#include "motion/metrology/linear/scale_certificate.h"

#include <QString>

#include <string>
#include <string_view>

namespace dev::files::accuracy {

constexpr const char* kScaleCertificateSchema = "benchpilot.scale-certificate";
constexpr int kScaleCertificateVersion = 1;

/// The scale a certificate must be of: its pitch and its graduated length from 0.
struct ScaleGeometry {
    double pitchMm = 0.1;
    double lengthMm = 100;
};

using ScaleCertificateRead = motion::msg::Checked<motion::metrology::ScaleCertificate>;

ScaleCertificateRead scaleCertificateFromCsv(std::string_view text, std::string_view fileName, const ScaleGeometry& scale);
ScaleCertificateRead loadScaleCertificateFile(const QString& path, const ScaleGeometry& scale);
std::string scaleCertificateToCsv(const motion::metrology::ScaleCertificate& c);

} // namespace dev::files::accuracy
