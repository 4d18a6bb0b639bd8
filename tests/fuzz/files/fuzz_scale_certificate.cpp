// Fuzz target "scale-certificate": the reader of a glass scale's calibration certificate.
// Invariants: no crash; a refusal says where and what; an accepted certificate writes
// out, reads back and writes out the same, and interpolates a finite deviation.
#include "fuzz_files.h"

#include "device/files/accuracy/scale_certificate_csv.h"

#include <cmath>

namespace {

void checkScaleCertificate(std::string_view input)
{
    using namespace dev::files::accuracy;
    const ScaleGeometry scale;
    const ScaleCertificateRead r = scaleCertificateFromCsv(input, "fuzz.csv", scale);
    for (const motion::msg::Problem& p : r.problems())
        if (p.file != "fuzz.csv" || p.line < 1 || p.message.id.empty())
            fuzzfiles::fail("a problem that does not say where or what: " + motion::msg::debugFormat(r.problems()));
    if (!r.ok() && r.problems().empty())
        fuzzfiles::fail("refused without a problem");
    if (!r.ok())
        return;
    const std::string once = scaleCertificateToCsv(*r);
    const ScaleCertificateRead again = scaleCertificateFromCsv(once, "again.csv", scale);
    if (!again.ok())
        fuzzfiles::fail("a written certificate does not read back: " + motion::msg::debugFormat(again.problems()));
    if (scaleCertificateToCsv(*again) != once)
        fuzzfiles::fail("write → read → write changed the certificate");
    for (double mm : {-1.0, 0.0, 33.3, 50.0, 100.0, 200.0})
        if (!std::isfinite(r->deviationAtUm(mm)))
            fuzzfiles::fail("a deviation that is not finite");
}

} // namespace

BP_FUZZ_FILE_TARGET({"scale-certificate", [] { return fuzzfiles::exampleFiles(".scale-certificate.csv"); }, checkScaleCertificate});
