#pragma once
// The gains of the tuning target: edited in continuous form (Kp, Ki in 1/s,
// Kd in s), with the discrete per-period gains the device runs shown beside
// them, Apply / Revert / Save to device, and the history of applied sets.
#include "motion/control/gains.h"

#include <QDateTime>

#include <optional>
#include <QWidget>

class QLabel;
class QPushButton;
class QTableWidget;

namespace ui {

class NumberField;

class GainsPanel : public QWidget {
    Q_OBJECT
public:
    struct HistoryEntry {
        QDateTime time;
        QString source;  ///< who or what produced the set: "read from the device", "Z-N relay: zn-pid", …
        motion::control::DiscreteGains gains;
    };

    explicit GainsPanel(QWidget* parent = nullptr);

    /// A new target: its loop period, whether it has a device to save to, and its gains now.
    void setTarget(const QString& name, double periodS, bool device, const motion::control::DiscreteGains& gains, const QString& source);
    /// No target (yet): the editors and the history are emptied.
    void clearTarget(const QString& why);
    /// The set now in force (after Apply, a read-back, a revert); recorded in the history.
    void setInForce(const motion::control::DiscreteGains& gains, const QString& source);
    /// Puts a set into the editors without applying it.
    void setEdited(const motion::control::DiscreteGains& gains);
    /// The editors' set in discrete form; nullopt while a field is not a valid gain (shown why).
    std::optional<motion::control::DiscreteGains> edited() const;
    const motion::control::DiscreteGains& inForce() const { return m_inForce; }
    double periodS() const { return m_periodS; }
    const QList<HistoryEntry>& history() const { return m_history; }
    /// The set before the one in force (what Revert applies); nullopt if none.
    std::optional<HistoryEntry> previous() const;
    void setBusy(bool busy);
    /// Why Apply is not possible now (an invalid entry, or one still being typed); empty when it is.
    QString problem() const;
    /// The fields hold something other than the set in force (a different set, or an entry that is no set).
    bool hasUnappliedEdits() const;

signals:
    void applyRequested(const motion::control::DiscreteGains& gains, const QString& source);
    void saveRequested(const motion::control::DiscreteGains& gains);
    void revertRequested(const motion::control::DiscreteGains& gains, const QString& source);
    void readBackRequested();

private:
    void showEdited();
    void refreshButtons();
    void addHistory(const QString& source, const motion::control::DiscreteGains& g);

    QLabel* m_title;
    QLabel* m_form;
    NumberField* m_edit[3];
    QLabel* m_discrete[3];
    QLabel* m_times;
    QPushButton* m_apply;
    QPushButton* m_revert;
    QPushButton* m_save;
    QPushButton* m_read;
    QTableWidget* m_table;
    double m_periodS = 1e-3;
    bool m_device = false;
    bool m_busy = false;
    bool m_hasTarget = false;
    motion::control::DiscreteGains m_inForce;
    QList<HistoryEntry> m_history;
};

/// "Kp 2.56 · Ki 986 /s · Kd 1.66 ms": a continuous set, for legends and history.
QString describeGains(const motion::control::DiscreteGains& g, double periodS);

} // namespace ui
