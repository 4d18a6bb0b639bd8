#pragma once
// Picks the channels of one plot of the stack: a plot chooser and a tree of both
// instruments' channels with check boxes. It holds no plot state of its own: the
// owner says which channels the current plot has and hears toggles.
#include "widgets/plot_source.h"

#include <QWidget>

class QComboBox;
class QTreeWidget;
class QTreeWidgetItem;

namespace ui {

class ChannelPicker : public QWidget {
    Q_OBJECT
public:
    struct Entry {
        dev::tele::ChannelKey key;
        QString name, unit;
    };

    explicit ChannelPicker(QWidget* parent = nullptr);

    /// Replaces the channels listed for one instrument (0 analyzer, 1 stage).
    void setInstrumentChannels(int instrument, const QString& instrumentName, const QVector<Entry>& channels);
    int channelCount(int instrument) const;

    void setPlotCount(int count);
    int plotCount() const;
    void setCurrentPlot(int index);
    int currentPlot() const;
    /// Ticks exactly these channels (the current plot's) without emitting toggles.
    void showChecked(const QVector<dev::tele::ChannelKey>& channels);
    bool isChecked(const dev::tele::ChannelKey& key) const;
    /// Expands the instruments that have ticked channels and folds the others
    /// (all expanded when nothing is ticked), so a plot's channels are in view.
    void revealChecked();
    /// As if the person ticked or unticked the box: emits channelToggled on a change.
    bool setChecked(const dev::tele::ChannelKey& key, bool on);

signals:
    void channelToggled(int plot, const dev::tele::ChannelKey& key, bool on);
    void currentPlotChanged(int index);

private:
    QTreeWidgetItem* itemFor(const dev::tele::ChannelKey& key) const;
    QTreeWidgetItem* instrumentItem(int instrument);

    QComboBox* m_plot;
    QTreeWidget* m_tree;
    int m_quiet = 0;  ///< > 0 while the owner sets check states
};

} // namespace ui
