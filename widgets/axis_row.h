#pragma once
// One axis on the Jog screen: readouts, lamps and the controls that move it.
// Lives in its screen's grid so the columns of all axes line up.
#include "device/client/instrument_types.h"

#include <QObject>

class QComboBox;
class QGridLayout;
class QLabel;
class QLineEdit;
class QPushButton;
class QToolButton;

namespace ui {

class StatusLamp;

class AxisRow : public QObject {
    Q_OBJECT
public:
    AxisRow(int axis, const dev::AxisDescriptor& descriptor, dev::proto::DeviceKind kind, QGridLayout* grid, int row,
            QWidget* parent);
    ~AxisRow() override;

    int axis() const { return m_axis; }
    void showReadout(const dev::AxisReadout& readout);
    /// No live link: the lamps say unknown and the positions are marked as the last
    /// ones read, so nothing from before reads as the machine's state now.
    void showStale();
    bool stale() const { return m_stale; }
    void showLimits(const dev::SoftLimits& limits);
    /// The step the operator picked, in axis units; nullopt (and a red field) when it does not parse.
    std::optional<double> step() const;
    int decimals() const { return m_decimals; }
    /// Enabled when `whyNot` is empty; otherwise the controls say why in their tooltips.
    void setEnabled(const QString& whyNot);
    /// Words the row's texts again in the language now in force.
    void retranslateUi();
    static QList<double> stepPresets(const dev::AxisDescriptor& d, dev::proto::DeviceKind kind);

signals:
    void stepRequested(int axis, double delta);
    void holdStarted(int axis, int direction);
    void holdEnded(int axis);
    void homeRequested(int axis);
    void zeroRequested(int axis);
    void goToRequested(int axis, double target);
    void problem(const QString& message);
    /// Enter in the Step or Go-to field: the operator is done typing (the keys jog again).
    void doneTyping();

private:
    QString format(double v) const;
    void showLampTips();

    int m_axis;
    dev::AxisDescriptor m_desc;
    dev::proto::DeviceKind m_kind;
    int m_decimals;
    QLabel* m_name;
    QLabel* m_commanded;
    QLabel* m_measured;
    StatusLamp* m_homed;
    StatusLamp* m_homeSwitch;
    StatusLamp* m_limitSwitch;
    StatusLamp* m_moving;
    QComboBox* m_step;
    QToolButton* m_stepMinus;
    QToolButton* m_stepPlus;
    QToolButton* m_holdMinus;
    QToolButton* m_holdPlus;
    QPushButton* m_home;
    QPushButton* m_zero;
    QLineEdit* m_target;
    QPushButton* m_go;
    QLabel* m_limits;
    QList<QWidget*> m_controls;
    QString m_whyNot;          ///< why the row's controls are disabled; empty: they are not
    bool m_isHomed = false;
    bool m_homing = false;
    bool m_stale = false;
};

} // namespace ui
