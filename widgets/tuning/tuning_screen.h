#pragma once
// The Tuning screen (docs/tuning.md): pick an instrument's closed-loop axis or a model
// plant; its gains (continuous form, discrete beside) with Apply / Revert /
// Save to device and their history; step tests overlaid with their metrics;
// the Ziegler–Nichols assistant. Everything long runs in one TuningRunner with
// progress, Abort and Resume; live telemetry comes through the shared hub.
#include "device/client/tuning_client.h"
#include "device/jobs/tuning/tuning_runner.h"
#include "motion/control/plant.h"

#include <QPointer>
#include <QTimer>
#include <QVariantMap>
#include <QWidget>

#include <functional>
#include <memory>

class QComboBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QTabWidget;

namespace dev::tele {
class TelemetryHub;
}

namespace ui {

class GainsPanel;
class StepTestPanel;
class ZnPanel;

class TuningScreen : public QWidget {
    Q_OBJECT
public:
    /// Asks for a file; empty = cancelled. `save`: a file to write, else one to open.
    using FileChooser = std::function<QString(const QString& title, const QString& filter, bool save)>;
    /// Asked before gains go to a machine from a rules row; true = go ahead.
    using Confirm = std::function<bool(const QString& question)>;
    static constexpr const char* kModelTarget = "model";

    explicit TuningScreen(dev::tele::TelemetryHub* hub, QWidget* parent = nullptr);
    ~TuningScreen() override;
    /// Its closed-loop axes become targets through its tuning(); an instrument without
    /// gains to tune says why under the target list.
    void addInstrument(int index, const QString& name, dev::Instrument* client);
    /// The instrument's name in a new language: the target list is worded anew.
    void renameInstrument(int index, const QString& name);
    void setFileChooser(FileChooser chooser) { m_chooser = std::move(chooser); }
    void setConfirm(Confirm confirm) { m_confirm = std::move(confirm); }

    /// "Stage X", "Stage Y", …, then "Model plant".
    QStringList targetNames() const;
    bool selectTarget(const QString& name);
    QString currentTarget() const;
    /// Parses and uses a model plant spec; false with the parser's message (naming the field).
    bool setModelPlant(const QString& spec, QString* error = nullptr);

    bool runStepTest();
    bool startAssistant();
    void abort();
    bool resume();

    bool saveResults(const QString& path = {});
    bool loadResults(const QString& path = {});
    bool hasResult() const { return m_haveResult; }
    const motion::control::TuningResult& lastResult() const { return m_lastResult; }

    /// What the app keeps between runs (QSettings lives in app/).
    QVariantMap saveState() const;
    void restoreState(const QVariantMap& state);

    GainsPanel* gains() const { return m_gains; }
    StepTestPanel* stepTests() const { return m_steps; }
    ZnPanel* assistant() const { return m_zn; }
    dev::TuningRunner* runner() const { return m_runner; }
    QTabWidget* tabs() const { return m_tabs; }
    QString statusText() const;

signals:
    /// A sentence for the banner: a refusal, a lost link, an E-stop during a run.
    void problem(const QString& message);

protected:
    void showEvent(QShowEvent* event) override;
    void hideEvent(QHideEvent* event) override;

private:
    struct Instrument {
        int index = 0;
        QString name;
        QPointer<dev::Instrument> client;
        QPointer<dev::TuningClient> tuning;  ///< client->tuning(), fetched again when its parts are replaced
        QMetaObject::Connection gainsWatch;
    };
    struct Choice {
        QString name;
        int instrument = -1;  ///< into m_instruments; −1: the model plant
        int axis = -1;
    };

    void rebuildTargets();
    void watchTuning(int instrument);
    void onTargetChosen();
    void readGains();
    void applyGains(const motion::control::DiscreteGains& g, bool save, const QString& source);
    void onRunnerState(dev::TuningRunner::State s);
    void onFinished(bool ok, const QString& text);
    void updateLiveWant();
    bool m_deviceTestRunning = false;
    /// The operator (or a script, or saved settings) picked the target: a rebuilt list keeps it.
    /// Until then the first instrument axis is taken as soon as one is there.
    bool m_targetPicked = false;
    QString m_savedTarget;  ///< from the settings, taken when it is offered
    int m_ownGainChanges = 0;  ///< SET_GAINS of ours not yet announced back by the device
    void drawLive();
    void refreshReady();
    void say(const QString& text, bool isProblem = false);
    const Choice* choice() const;
    Instrument* instrumentOf(const Choice& c);

    QPointer<dev::tele::TelemetryHub> m_hub;  ///< the main window's: it may go before this screen does
    QList<Instrument> m_instruments;
    QList<Choice> m_choices;
    QComboBox* m_target;
    QLineEdit* m_plant;
    QLabel* m_plantError;
    QLabel* m_unavailable;  ///< why an identified instrument offers no target
    QLabel* m_live;
    QTabWidget* m_tabs;
    GainsPanel* m_gains;
    StepTestPanel* m_steps;
    ZnPanel* m_zn;
    QProgressBar* m_progress;
    QLabel* m_status;
    QPushButton* m_abort;
    QPushButton* m_resume;
    QPushButton* m_save;
    QPushButton* m_open;
    dev::TuningRunner* m_runner;
    std::unique_ptr<dev::TuningTarget> m_targetObj;
    motion::control::PlantSpec m_plantSpec;
    motion::control::DiscreteGains m_modelGains{0.5, 0.00005, 0};
    motion::control::DiscreteGains m_runGains;  ///< what the running step test runs with, for its legend
    QString m_runLegend;
    motion::control::TuningResult m_lastResult;
    bool m_haveResult = false;
    QTimer m_liveTimer;
    double m_liveStartS = -1;  ///< device time the live run began at
    FileChooser m_chooser;
    Confirm m_confirm;
    QString m_lastStatus;
};

} // namespace ui
