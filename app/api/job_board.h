#pragma once
// Jobs running on the bench, for the `jobs` topic and the GUI's API panel: those a
// script started through the API (each call that needs control, while it runs) and
// those the operator started on a screen (the Plates, Scan and Patterns runners).
//
// A job a script started keeps running when the script loses control (taken back,
// disconnected, heartbeats stopped): it is then handed over, its owner becomes the
// operator, and the GUI says so. Bounded: finished jobs beyond kKeepFinished go first.
#include <QDateTime>
#include <QJsonObject>
#include <QObject>
#include <QString>

#include <vector>

namespace dev::jobs {
class AccuracyRunner;
class CircleRunner;
class PatternRunner;
class RecipeRunner;
class ScanRunner;
}

namespace app::api {

struct Job {
    QString id;          ///< "j7"
    QString kind;        ///< "recipe.run", "scan.run", "device.move", "plates screen"
    QString instrument;  ///< "analyzer", "stage"
    QString owner;       ///< the client's name, or "operator"
    QString startedBy;   ///< who started it (stays when it is handed over)
    QDateTime started;
    QString state = QStringLiteral("running");  ///< running, finished, stopped
    QJsonObject progress;  ///< the job's latest progress line (well, tile, segment, ETA)
    bool handedOver = false;
    bool fromApi = false;
    QJsonObject toJson() const;
};

class JobBoard : public QObject {
    Q_OBJECT
public:
    static constexpr int kKeepFinished = 20;
    static inline const QString kOperator = QStringLiteral("operator");

    explicit JobBoard(QObject* parent = nullptr);

    QString add(const QString& kind, const QString& instrument, const QString& owner, bool fromApi);
    void setProgress(const QString& id, const QJsonObject& progress);
    void finish(const QString& id, const QString& state);
    /// The job's owner lost control; it goes on as the operator's.
    void handOver(const QString& id);
    const Job* job(const QString& id) const;
    const std::vector<Job>& all() const { return m_jobs; }
    bool anyRunning(const QString& instrument, bool fromApi) const;
    /// Increases with every change (the `jobs` topic's sequence).
    quint64 seq() const { return m_seq; }

signals:
    void changed(const QString& id);

private:
    Job* find(const QString& id);
    void trim();

    std::vector<Job> m_jobs;
    int m_next = 1;
    quint64 m_seq = 0;
};

/// Puts a screen's runner on the board while it runs (the operator's jobs).
void watchRecipeRunner(JobBoard& board, dev::jobs::RecipeRunner* runner, const QString& instrument, const QString& kind);
void watchScanRunner(JobBoard& board, dev::jobs::ScanRunner* runner, const QString& instrument, const QString& kind);
void watchPatternRunner(JobBoard& board, dev::jobs::PatternRunner* runner, const QString& instrument, const QString& kind);
/// The Calibration screen makes a runner per run: watch each as it starts (job_board_accuracy.cpp).
void watchAccuracyRunner(JobBoard& board, dev::jobs::AccuracyRunner* runner, const QString& instrument, const QString& kind);
void watchCircleRunner(JobBoard& board, dev::jobs::CircleRunner* runner, const QString& instrument, const QString& kind);

} // namespace app::api
