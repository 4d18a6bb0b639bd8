#pragma once
// Runs a stitching scan on the stage: for each tile it moves, waits for the
// device's MotionDone, then for the grating to read within the plan's tolerance
// of the target (on the status replies, not a busy loop), takes the position and
// device time at that moment as the trigger, dwells for the exposure, and logs
// the tile. Pause waits for the tile in progress; Abort stops the stage at once.
// A run that stopped for any reason (abort, E-stop, a refused move, a lost link,
// a crash of the program) continues from its run log at the next tile.
//
// With a camera (setCamera), the tile is taken by the camera instead of a dwell: the next
// frame started after the settle; the stage moves on once the exposure is over, while the
// image is written; the tile's run-log line (with "image" and "sha256") is appended when
// the file is whole. A resumed run takes again a tile whose image is missing or does not
// match its checksum.
//
// It needs no protocol of its own: a move, the MotionDone event and a status reading
// (grating positions with the device's clock) carry everything (docs/scan.md), so it
// runs on any dev::Instrument. Estimates use the limits the device reported
// (dev::jobs::stageModelOf).
#include "device/client/instrument.h"
#include "device/files/scan_run_log.h"
#include "device/jobs/scan_tile_camera.h"
#include "motion/plans/scan/scan_estimate.h"
#include "motion/records/position_record.h"

#include <QFile>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include <optional>
#include <vector>

namespace dev::jobs {

class ScanRunner : public QObject {
    Q_OBJECT
public:
    enum class State {
        Idle,      ///< nothing prepared, or prepared and not started
        Running,
        Pausing,   ///< Pause pressed: the tile in progress finishes first
        Paused,
        Stopped,   ///< aborted or interrupted (see the problem message); Resume continues
        Finished,
    };

    explicit ScanRunner(dev::Instrument* client, QObject* parent = nullptr);
    ~ScanRunner() override;

    /// Why prepare() said no, for callers that offer a way out: they branch on
    /// this, never on the (translated) message.
    enum class Refusal {
        None,
        OtherScansLog,  ///< the folder holds the run log of another plan: `restart` keeps it aside and begins anew
        Other,          ///< anything else (a bad plan, a folder that cannot be made or read, a running scan)
    };

    /// Takes the plan and the folder its run log and exports go to. A run log there
    /// of the same tiles is continued; one of other tiles is refused unless
    /// `restart`, which keeps it under another name and starts afresh.
    bool prepare(const motion::scan::ScanPlan& plan, const QString& folder, bool restart, motion::msg::Message* error,
                 Refusal* why = nullptr);

    /// The camera that takes each tile (nullptr: none, the plan's exposure is a dwell).
    /// Set it before prepare(): resuming checks the images, and the estimate counts it.
    void setCamera(ScanTileCamera* camera);
    ScanTileCamera* camera() const { return m_camera; }
    /// The tile's image as the run log has it (empty file: none).
    const dev::files::scan::TileImageRef& image(int tile) const { return m_images.at(static_cast<std::size_t>(tile)); }

    /// What keeps the prepared run from starting now, one message each (scan.run.*); empty = ready.
    std::vector<motion::msg::Message> preflight() const;
    /// Starts, or resumes after a pause or a stop, at the first tile not yet taken.
    bool start(motion::msg::Message* error);
    void pause();
    void abort();

    dev::Instrument* instrument() const { return m_client; }
    State state() const { return m_state; }
    bool isActive() const { return m_state == State::Running || m_state == State::Pausing; }
    const motion::scan::ScanPlan& plan() const { return m_plan; }
    const motion::scan::ScanLayout& layout() const { return m_layout; }
    const motion::scan::ScanEstimate& estimate() const { return m_estimate; }
    /// One per tile in visiting order; measured once the tile is taken.
    const std::vector<motion::PositionRecord>& records() const { return m_records; }
    int takenTiles() const { return m_takenCount; }
    int totalTiles() const { return static_cast<int>(m_layout.tiles.size()); }
    bool isTaken(int tile) const { return tile >= 0 && tile < totalTiles() && m_taken[static_cast<std::size_t>(tile)]; }
    /// The tile being worked on (moving, settling, exposing), or −1.
    int currentTile() const;
    /// Seconds left: the estimate for the tiles not taken, scaled by how this run has
    /// kept to it on the device's clock.
    double etaS() const;
    QString folder() const { return m_folder; }
    QString logPath() const;
    /// Writes TileConfiguration.txt, positions.pos and scan.csv into the folder.
    bool writeExports(QStringList* written, motion::msg::Message* error) const;

    /// The state's term for people ("scan.state.running"), worded by ui::words::term.
    static const char* stateTerm(State s);

signals:
    void stateChanged(dev::jobs::ScanRunner::State state);
    void progress(int taken, int total, double etaS);
    /// The stage sits within tolerance at `tile`: where a camera would be triggered.
    void triggered(int tile, quint64 deviceTimeUs);
    void tileTaken(int tile);
    /// Why the run stopped or would not start (scan.run.*, worded by ui::words::text).
    void problem(const motion::msg::Message& message);
    /// Every tile taken; `exports` are the files written.
    void finished(const QStringList& exports);

private:
    enum class Phase { None, Moving, Settling, Exposing };

    void setState(State s);
    void nextWaypoint();
    void onMoveAccepted(const std::optional<dev::RequestError>& error);
    void onEvent(const dev::DeviceEvent& e);
    /// Both axes owe no MotionDone any more (or the status showed them at rest on target).
    void onMoveArrived();
    /// A MotionDone lost on a noisy link: the polled status shows the move arrived.
    void checkArrivedByStatus(const dev::InstrumentStatus& s);
    void requestStatus();
    void checkSettled(const std::vector<double>& measuredMm, quint64 deviceTimeUs);
    void onExposureEnd();
    /// The camera's side of a tile (scan_runner_camera.cpp).
    void takeWithCamera(int tile);
    void onCameraExposed(int tile);
    void onImageWritten(int tile, const dev::jobs::TileImage& image);
    void onCameraFailed(int tile, const motion::msg::Message& reason);
    /// A tile of the log whose image is missing, cut short or not the one logged.
    bool imageIntact(const dev::files::scan::TileImageRef& image) const;
    void addCameraTimeToEstimate();
    void finishRun();
    void stopWith(const motion::msg::Message& message, bool stopStage);
    /// A plan that runs with the stage's own compensation: reads whether X and Y have it
    /// enabled (again whenever the device says it changed), for preflight().
    void refreshCompensation();
    /// The folder's run log: continued when it is of these tiles, refused (`why`) when it is
    /// another plan's, set aside when `restart`. `fresh` says whether a new log is to begin.
    bool adoptRunLog(std::uint64_t fingerprint, bool restart, bool* fresh, motion::msg::Message* error, Refusal* why);
    /// Marks the log's tiles taken, and writes the log out again without a torn last line.
    bool continueFromLog(const dev::files::scan::RunLog& log, std::uint64_t fingerprint, motion::msg::Message* error);
    bool openLog(motion::msg::Message* error);
    bool appendLog(const std::string& line, motion::msg::Message* error);
    int waypointToResumeAt() const;
    motion::scan::Point2 commanded(int pathIndex) const;
    /// The `tile` argument: scan.run.tile {tile, total, label}, or scan.run.the_start.
    motion::msg::Arg tileArg(int tile) const;

    dev::Instrument* m_client;
    motion::scan::ScanPlan m_plan;
    motion::scan::ScanLayout m_layout;
    motion::scan::ScanEstimate m_estimate;
    motion::scan::StageModel m_stageModel;  ///< the device's limits as of prepare() or its last change
    std::vector<motion::PositionRecord> m_records;
    std::vector<char> m_taken;
    int m_takenCount = 0;
    QString m_folder;
    QFile m_log;
    bool m_prepared = false;

    State m_state = State::Idle;
    Phase m_phase = Phase::None;
    int m_pathIndex = 0;                 ///< the waypoint being worked on
    std::optional<motion::scan::Point2> m_extraApproach;  ///< resume: an overtravel point not in the path
    bool m_onExtra = false;              ///< the move in progress goes to m_extraApproach
    unsigned m_waitingAxes = 0;          ///< bit per axis still owing MotionDone
    quint64 m_motionDoneUs = 0;          ///< device time of the last MotionDone of this move
    motion::scan::Point2 m_moveTarget{}; ///< where the move in flight goes (mm)
    bool m_moveAccepted = false;         ///< the device replied to the move in flight
    int m_restPolls = 0;                 ///< status readings since the reply showing it at rest on target
    std::vector<double> m_triggerMm;
    quint64 m_triggerUs = 0;
    double m_lastOffUm[2] = {0, 0};      ///< how far from the target the last status read, for messages
    QTimer m_exposure, m_settleTimeout;
    QPointer<ScanTileCamera> m_camera;
    QList<QMetaObject::Connection> m_cameraConnections;
    std::vector<dev::files::scan::TileImageRef> m_images;  ///< per tile, as logged
    QTimer m_cameraTimeout;               ///< a camera that never ends the exposure stops the run
    bool m_finishWhenWritten = false;     ///< every tile exposed; finishing waits for the last images
    int m_sessionFirstTaken = 0;         ///< tiles taken when this start or resume began
    int m_sessionFirstTile = -1;         ///< the first tile this session took, or −1
    double m_leadInS = 0;                ///< estimated move from where the stage stood to the session's first waypoint
    QList<QMetaObject::Connection> m_clientConnections;
    std::optional<bool> m_compEnabled[2];    ///< X, Y: the device's compensation enabled; empty until read
    QPointer<QObject> m_compWatched;         ///< the compensation part whose changes are followed
};

} // namespace dev::jobs

Q_DECLARE_METATYPE(dev::jobs::ScanRunner::State)
