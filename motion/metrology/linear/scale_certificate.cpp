#include "motion/metrology/linear/scale_certificate.h"

#include <algorithm>

namespace motion::metrology {

double ScaleCertificate::deviationAtUm(double mm) const
{
    const std::size_t n = std::min(graduationMm.size(), deviationUm.size());
    if (n == 0)
        return 0;
    if (mm <= graduationMm.front())
        return deviationUm.front();
    if (mm >= graduationMm[n - 1])
        return deviationUm[n - 1];
    const auto it = std::upper_bound(graduationMm.begin(), graduationMm.begin() + static_cast<std::ptrdiff_t>(n), mm);
    const std::size_t k = static_cast<std::size_t>(it - graduationMm.begin());
    const double t = (mm - graduationMm[k - 1]) / (graduationMm[k] - graduationMm[k - 1]);
    return deviationUm[k - 1] + t * (deviationUm[k] - deviationUm[k - 1]);
}

} // namespace motion::metrology
