#pragma once
// The calibration wizard of a deck slot: for each of its three teach wells
// (A1, the end of row A, the start of the last row) go near it, put the tip over
// its centre with the jog pad, and record; the fit (motion/plans/plates/
// calibration.h) shows rotation, scale and each point's residual, warns past
// 0.2 mm, and is kept per slot when saved.
#include "device/client/instrument.h"
#include "motion/plans/plates/calibration.h"
#include "motion/plans/plates/deck.h"

#include <QWidget>

#include <functional>
#include <map>

class QComboBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace ui {

class JogPad;

class CalibrationPanel : public QWidget {
    Q_OBJECT
public:
    using Confirm = std::function<bool(const QString& question)>;

    explicit CalibrationPanel(dev::Instrument* client, QWidget* parent = nullptr);
    void setConfirm(Confirm confirm) { m_confirm = std::move(confirm); }
    void setDeck(const motion::plates::Deck& deck);
    /// What sits in each slot (from the recipe) and the Z to travel at there.
    void setSlotLabware(const std::map<std::string, motion::plates::Labware>& bySlot, const std::map<std::string, double>& safeZBySlot);
    void setCalibrations(const std::vector<motion::plates::SlotCalibration>& calibrations);
    const std::vector<motion::plates::SlotCalibration>& calibrations() const { return m_calibrations; }

    QString slotId() const;
    void setSlot(const QString& id);
    /// Records the tip's position as teach point `index` (0–2), as the button does.
    void recordPoint(int index);
    /// The fit of the points taught so far (empty before three).
    const std::optional<motion::plates::CalibrationFit>& fit() const { return m_fit; }
    /// Keeps the fit for the slot (as "Save calibration" does); false without a fit.
    bool saveSlot();

signals:
    void calibrationsChanged();
    void problem(const QString& message);

protected:
    /// The shipped deck's slot names are worded per language (ui::words::shippedName).
    void changeEvent(QEvent* event) override;

private:
    void rebuild();
    void refit();
    void goTo(int index);
    const motion::plates::Labware* labware() const;
    motion::plates::PlateTransform currentTransform() const;

    dev::Instrument* m_client;
    Confirm m_confirm;
    motion::plates::Deck m_deck;
    std::map<std::string, motion::plates::Labware> m_bySlot;
    std::map<std::string, double> m_safeZ;
    std::vector<motion::plates::SlotCalibration> m_calibrations;
    std::vector<motion::plates::TeachPoint> m_points;
    std::vector<bool> m_recorded;
    std::optional<motion::plates::CalibrationFit> m_fit;
    QComboBox* m_slot;
    QComboBox* m_model;
    QLabel* m_status;
    QTableWidget* m_table;
    JogPad* m_pad;
    QLabel* m_result;
    QLabel* m_warnings;
    QPushButton* m_save;
    QPushButton* m_forget;
};

} // namespace ui
