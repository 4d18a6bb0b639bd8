#pragma once
// Runs a grid map (motion/metrology/grid/grid_map_test.h) on an XY stage with the camera
// on a grid plate as its reading source (dev::camera::DotReadingSource, or any source of
// two-axis readings): it first finds the dot nearest the image centre where the stage
// stands (unless the test gives the start), then visits the nodes row by row, each row
// led in from below on both axes, waits for arrival and the dwell on the device's clock,
// and takes a reading that says where the work point truly was against the plate. A
// bidirectional test then reads every node again in reverse order, led in from above.
//
// Every reading of either pass, or its failure, is appended to the run log
// (grid-map.run-log.jsonl in the run's folder) before the next node. A dot the camera
// cannot find is that node's failure (the source keeps the image): the run goes on, or
// stops when the test says so. A run that stopped for any reason (abort, E-stop, a
// refused move, a lost link, a crash), in either pass, continues from its log with the
// same start and never reads a node of either pass twice; the readings that failed are
// tried again. When every node has a reading the map is analysed
// (motion/metrology/grid/grid_map.h) and the readings CSV and the result JSON are written
// beside the log.
//
// Like the accuracy runner it needs nothing but moves, events and status readings.
// Everything it tells a person is a motion::msg::Message (accuracy.run.*, grid.run.*).
#include "device/client/instrument.h"
#include "device/jobs/accuracy/reading_source.h"
#include "device/jobs/arrival_by_status.h"
#include "motion/metrology/grid/grid_map.h"
#include "motion/metrology/grid/grid_map_test.h"

#include <QFile>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include <optional>
#include <vector>

namespace dev::jobs {

/// One reading of a run (a node in one pass), as read (or not).
struct GridNodeReading {
    bool read = false;
    double measuredXMm = 0, measuredYMm = 0;  ///< where the work point truly was against the plate
    std::string failure;                      ///< why not: the message's id ("" while not visited)
    std::string image;                        ///< a failed node's image, beside the log
};

class GridMapRunner : public QObject {
    Q_OBJECT
public:
    enum class State { Idle, Running, Stopped, Finished };

    explicit GridMapRunner(dev::Instrument* instrument, QObject* parent = nullptr);
    ~GridMapRunner() override;

    /// The test and its source (not owned; it must outlive the run) and the folder for the
    /// run log and the results. The test is checked against the instrument's travel from
    /// its start (a start found by the camera is checked when found). A log in the folder
    /// of the same test is continued; another's is refused unless `restart`, which keeps
    /// it aside. Problems carry the test's field paths.
    bool prepare(const motion::metrology::GridMapTest& test, ReadingSource* source, const QString& folder, bool restart,
                 motion::msg::Problems* problems);
    /// Starts, or continues, at the first node not read. Refused (why) when not prepared,
    /// not connected, X or Y not homed, E-stop.
    bool start(motion::msg::Message* why = nullptr);
    void abort();

    State state() const { return m_state; }
    bool isActive() const { return m_state == State::Running; }
    const motion::metrology::GridMapTest& test() const { return m_test; }
    bool hasStart() const { return m_haveStart; }
    double startXMm() const { return m_startXMm; }
    double startYMm() const { return m_startYMm; }
    const std::vector<motion::metrology::GridMapStop>& stops() const { return m_stops; }
    const std::vector<GridNodeReading>& nodes() const { return m_nodes; }
    int nodesRead() const;
    int nodesFailed() const;
    /// Readings in the run: the nodes, twice when bidirectional. stops(), nodes(),
    /// progress() and the node signals count in readings, in the order they are taken.
    int totalNodes() const { return static_cast<int>(m_stops.size()); }

    /// The map of every node read: nullopt until every node has a reading.
    std::optional<motion::metrology::GridMapResult> result() const;
    motion::metrology::GridMapInput input() const;

    QString folder() const { return m_folder; }
    QString logPath() const;
    /// "<folder>/grid-map": the results are <base>.readings.csv and .grid-map-result.json.
    QString basePath() const;
    const QStringList& results() const { return m_results; }

    static const char* stateName(State s);

signals:
    void stateChanged(dev::jobs::GridMapRunner::State state);
    void progress(int visited, int total);
    void nodeRead(int node);
    void nodeFailed(int node, const motion::msg::Message& why);
    /// Why the run stopped, would not start, or finished without a map.
    void problem(const motion::msg::Message& message);
    /// Every node visited; `files` are the results written (none when a node has no reading).
    void finished(const QStringList& files);

private:
    enum class Phase { None, Locating, LeadIn, Target, Dwell, Reading };

    void setState(State s);
    void locateStart();
    void onStartFound(const TakeResult& r);
    void nextNode();
    int nextUnread() const;
    void moveTo(double xMm, double yMm, Phase phase);
    void onMoveAccepted(const std::optional<dev::RequestError>& error, quint64 generation);
    void onEvent(const dev::DeviceEvent& e);
    void onArrived();
    void pollDwell();
    void takeReading();
    void onReading(int k, const TakeResult& r);
    void stopWith(const motion::msg::Message& why, bool stopAxes);
    bool openLog(bool restart, motion::msg::Problems* problems);
    bool appendLog(const std::string& line);
    void finish();
    void writeResults();
    quint8 axisMask() const;

    QPointer<dev::Instrument> m_instrument;
    motion::metrology::GridMapTest m_test;
    int m_axisX = 0, m_axisY = 1;
    bool m_haveStart = false;
    double m_startXMm = 0, m_startYMm = 0;
    std::vector<motion::metrology::GridMapStop> m_stops;
    std::vector<GridNodeReading> m_nodes;
    QPointer<ReadingSource> m_source;
    QString m_folder;
    QFile m_log;
    bool m_prepared = false;
    QStringList m_results;

    State m_state = State::Idle;
    Phase m_phase = Phase::None;
    int m_current = -1;                ///< the node being worked on
    int m_previous = -1;               ///< the stop visited last in this session (-1: none yet)
    quint64 m_generation = 0;          ///< callbacks of an aborted step are ignored
    unsigned m_waitingAxes = 0;
    bool m_moveAccepted = false;
    quint64 m_arrivedUs = 0;
    ArrivalByStatus m_arrival;
    QTimer m_poll;
    QList<QMetaObject::Connection> m_connections;
};

} // namespace dev::jobs

Q_DECLARE_METATYPE(dev::jobs::GridMapRunner::State)
