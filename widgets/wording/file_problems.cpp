// Problems found in files, worded with their place: what the CLI prints and the
// screens list when a recipe, plan, pattern or tuning file is refused.
#include "widgets/wording/wording.h"

#include "device/files/json_fields.h"
#include "motion/control/experiment.h"

#include <QCoreApplication>

#include <algorithm>

namespace words {
namespace {

class FileProblemWords {
    Q_DECLARE_TR_FUNCTIONS(words::FileWords)
public:
    static QString line(const QString& file, const jsonio::Problem& p)
    {
        const QString sentence = p.warning ? tr("warning: %1").arg(text(p.message)) : text(p.message);
        if (p.position.line <= 0)
            return QStringLiteral("%1: %2").arg(file, sentence);
        const QString at = QStringLiteral("%1:%2:%3").arg(file).arg(p.position.line).arg(p.position.column);
        return p.path.empty() ? QStringLiteral("%1: %2").arg(at, sentence)
                              : QStringLiteral("%1: %2: %3").arg(at, QString::fromStdString(p.path), sentence);
    }
    static QString line(const msg::Problem& p)
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

QString problem(const msg::Problem& p) { return FileProblemWords::line(p); }

QStringList problems(const msg::Problems& list)
{
    QStringList out;
    for (const msg::Problem& p : list)
        out << problem(p);
    return out;
}

QString fileProblem(const QString& file, const jsonio::Problem& problem) { return FileProblemWords::line(file, problem); }

QStringList fileProblems(const jsonio::Problems& problems, const QString& file)
{
    std::vector<jsonio::FileProblem> sorted;
    jsonio::appendSorted(sorted, problems, file.toStdString());
    return fileProblems(sorted);
}

QStringList fileProblems(const std::vector<jsonio::FileProblem>& problems)
{
    QStringList out;
    for (const jsonio::FileProblem& p : problems)
        out << fileProblem(QString::fromStdString(p.file), p.problem);
    return out;
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

} // namespace words
