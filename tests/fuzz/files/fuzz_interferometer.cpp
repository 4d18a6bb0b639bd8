// Fuzz targets "target-sequence" and "interferometer": the run's target sequence and
// an interferometer's export matched to it. Invariants: no crash; problems name the
// file and say what; a sequence read back writes the same text; an import has one
// reading per stop, each the stop's target, direction and cycle.
#include "fuzz_files.h"

#include "device/files/accuracy/interferometer_csv.h"

namespace {

const std::string kSequence = "index,target_mm,direction,cycle,time_s,settled\r\n"
                              "1,10,up,1,1.5,yes\r\n2,20,up,1,3,yes\r\n3,20,down,1,4.5,yes\r\n4,10,down,1,6,no\r\n"
                              "5,10,up,2,7.5,yes\r\n6,20,up,2,9,yes\r\n7,20,down,2,10.5,yes\r\n8,10,down,2,12,yes\r\n";

std::vector<dev::files::accuracy::SequenceStop> sequence() { return dev::files::accuracy::targetSequenceFromCsv(kSequence, "seq.csv").stops; }

void checkProblems(const motion::msg::Problems& problems, const char* file)
{
    for (const auto& p : problems)
        if (p.file != file || p.message.id.empty())
            fuzzfiles::fail("a problem that does not say where or what: " + motion::msg::debugFormat(problems));
}

void checkSequence(std::string_view input)
{
    const auto r = dev::files::accuracy::targetSequenceFromCsv(input, "fuzz.csv");
    checkProblems(r.problems, "fuzz.csv");
    if (!r.ok())
        return;
    const std::string again = dev::files::accuracy::targetSequenceCsv(r.stops);
    const auto back = dev::files::accuracy::targetSequenceFromCsv(again, "again.csv");
    if (!back.ok() || dev::files::accuracy::targetSequenceCsv(back.stops) != again)
        fuzzfiles::fail("a sequence that does not read back as written");
}

void checkImport(std::string_view input)
{
    const auto stops = sequence();
    const auto r = dev::files::accuracy::importInterferometerCsv(input, "fuzz.csv", stops);
    checkProblems(r.problems, "fuzz.csv");
    if (!r.ok())
        return;
    if (r.readings.size() != stops.size())
        fuzzfiles::fail("an import with a reading count other than the sequence's");
    for (std::size_t k = 0; k < stops.size(); ++k)
        if (r.readings[k].targetMm != stops[k].targetMm || r.readings[k].direction != stops[k].direction
            || r.readings[k].cycle != stops[k].cycle)
            fuzzfiles::fail("a reading matched to another stop");
}

} // namespace

BP_FUZZ_FILE_TARGET({"target-sequence", [] { return std::vector<std::string>{kSequence}; }, checkSequence});
BP_FUZZ_FILE_TARGET({"interferometer",
                     [] {
                         return std::vector<std::string>{
                             "position_mm,direction\n10.0011,fwd\n20.0021,fwd\n20.0001,bwd\n9.9995,bwd\n10.0012,fwd\n20.002,fwd\n20,bwd\n10,bwd\n",
                             "Target (mm),error_um\n10,1.1\n20,2.1\n20,0.1\n10,-0.5\n10,1.2\n20,2\n20,0\n10,0\n"};
                     },
                     checkImport});
