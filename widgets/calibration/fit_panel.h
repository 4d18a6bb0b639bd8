#pragma once
// The compensation panel of the Calibration screen (seed 002's method): the mean
// deviations of an axis test fitted with polynomials of orders 1–5 side by side (SSE,
// R², adjusted R²; the order chosen by adjusted R² unless the operator picks one),
// the residuals of the chosen one, and what the instrument holds for the axis, with
// Upload, Enable and Disable (and keeping it for power-up) through the instrument's
// compensation part. Saving the compensation as a file is the screen's (it has the
// file chooser).
#include "device/client/instrument.h"
#include "motion/metrology/compensation/compensation_model.h"
#include "motion/metrology/compensation/polynomial_fit.h"
#include "motion/metrology/linear/iso230_2.h"

#include <QPointer>
#include <QWidget>

#include <optional>

class QCheckBox;
class QComboBox;
class QCustomPlot;
class QCPGraph;
class QLabel;
class QPushButton;
class QTableWidget;

namespace ui {

class FitPanel : public QWidget {
    Q_OBJECT
public:
    explicit FitPanel(QWidget* parent = nullptr);

    /// The instrument whose compensation part uploads, reads and enables.
    void setInstrument(dev::Instrument* instrument);
    /// An axis test's result to fit (nullopt: nothing to fit yet).
    void setEvaluation(const std::string& axis, const std::optional<motion::metrology::Evaluation>& evaluation);
    /// The model the panel would upload: the chosen fit over the targets' range, with
    /// the backlash −B̄. Empty without a fit.
    std::optional<motion::metrology::CompensationModel> model() const;
    const motion::metrology::FitTable& fit() const { return m_fit; }
    /// Reads the device's state of the axis again.
    void refreshDevice();
    QString deviceText() const;

signals:
    /// A message for the banner (device refusals, what happened).
    void problem(const QString& message);
    void notice(const QString& message);
    /// The device's compensation of the axis changed (enabled, uploaded): before/after
    /// views want to know.
    void deviceChanged();

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();
    void refit();
    void updateButtons();
    void upload();
    void setEnabledOnDevice(bool on);
    int axisIndex() const;

    QPointer<dev::Instrument> m_instrument;
    std::string m_axis = "X";
    std::optional<motion::metrology::Evaluation> m_evaluation;
    motion::metrology::FitTable m_fit;
    QComboBox* m_order;
    QTableWidget* m_table;
    QLabel* m_curve;
    QCustomPlot* m_residuals;
    QCPGraph* m_residualGraph;
    QLabel* m_device;
    QCheckBox* m_keep;
    QPushButton *m_upload, *m_enable, *m_disable;
    QLabel *m_orderLabel, *m_residualsLabel;
    std::optional<bool> m_deviceHasModel, m_deviceEnabled, m_deviceApplied, m_deviceSaved;
    bool m_busy = false;
};

} // namespace ui
