// Problems worded with their place: what the CLI prints, the API's text says and the
// screens list when a plan, a form or a file is refused.
#include "widgets/wording/wording.h"

#include "device/files/json_fields.h"
#include "motion/control/experiment.h"

#include <QCoreApplication>

#include <algorithm>

namespace ui::words {
namespace {

class ProblemWords {
    Q_DECLARE_TR_FUNCTIONS(ui::words::FileWords)
public:
    static QString line(const motion::msg::Problem& p)
    {
        QString out = p.isWarning() ? tr("warning: %1").arg(text(p.message)) : text(p.message);
        if (!p.path.empty())
            out = QStringLiteral("%1: %2").arg(QString::fromStdString(p.path), out);
        QString at = QString::fromStdString(p.file);
        if (p.line > 0)
            at = at.isEmpty() ? QStringLiteral("%1:%2").arg(p.line).arg(p.column) : QStringLiteral("%1:%2:%3").arg(at).arg(p.line).arg(p.column);
        return at.isEmpty() ? out : QStringLiteral("%1: %2").arg(at, out);
    }
};

} // namespace

QString problem(const motion::msg::Problem& p) { return ProblemWords::line(p); }

QStringList problems(const motion::msg::Problems& list)
{
    QStringList out;
    for (const motion::msg::Problem& p : list)
        out << problem(p);
    return out;
}

QStringList fileProblems(const dev::files::json::Problems& problems, const QString& file)
{
    motion::msg::Problems sorted;
    dev::files::json::appendSorted(sorted, problems, file.toStdString());
    return ui::words::problems(sorted);
}

QString tuningOutcome(const std::string& key)
{
    static const std::pair<const char*, const char*> kOutcomes[] = {
        {"decays", "tuning.outcome.decays"},
        {"sustained", "tuning.outcome.sustained"},
        {"grows", "tuning.outcome.grows"},
        {"no oscillation", "tuning.outcome.no_oscillation"},
        {"hit the envelope", "tuning.outcome.hit_envelope"},
    };
    for (const auto& [name, id] : kOutcomes)
        if (key == name)
            return term(id);
    for (int r = 0; r <= motion::control::kMaxEndReason; ++r) {
        const auto reason = static_cast<motion::control::EndReason>(r);
        if (key == motion::control::endReasonName(reason))
            return term(motion::control::endReasonTerm(reason));
    }
    return QString::fromStdString(key);
}

} // namespace ui::words
