#include "widgets/channel_picker.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace ui {
namespace {
constexpr int kKeyRole = Qt::UserRole;            ///< channelId of a channel item
constexpr int kInstrumentRole = Qt::UserRole + 1; ///< instrument index of any item
constexpr int kIsChannelRole = Qt::UserRole + 2;

dev::tele::ChannelKey keyOf(const QTreeWidgetItem* item)
{
    const int id = item->data(0, kKeyRole).toInt();
    dev::tele::ChannelKey k;
    k.instrument = id >> 16;
    k.ref.axis = static_cast<std::uint8_t>((id >> 8) & 0xFF);
    k.ref.kind = static_cast<dev::proto::ChannelKind>(id & 0xFF);
    return k;
}
} // namespace

ChannelPicker::ChannelPicker(QWidget* parent) : QWidget(parent)
{
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
    auto* row = new QHBoxLayout;
    auto* label = new QLabel(tr("Channels of"), this);
    m_plot = new QComboBox(this);
    m_plot->setObjectName(QStringLiteral("plotChooser"));
    m_plot->setToolTip(tr("The plot whose channels are ticked below; clicking a plot also chooses it"));
    label->setBuddy(m_plot);
    row->addWidget(label);
    row->addWidget(m_plot, 1);
    v->addLayout(row);
    m_tree = new QTreeWidget(this);
    m_tree->setObjectName(QStringLiteral("channelTree"));
    m_tree->setColumnCount(2);
    m_tree->setHeaderLabels({tr("Channel"), tr("Unit")});
    m_tree->header()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_tree->header()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    m_tree->header()->setStretchLastSection(false);
    m_tree->setRootIsDecorated(true);
    m_tree->setUniformRowHeights(true);
    v->addWidget(m_tree, 1);
    setPlotCount(1);

    connect(m_plot, qOverload<int>(&QComboBox::currentIndexChanged), this, [this](int i) {
        if (!m_quiet && i >= 0)
            emit currentPlotChanged(i);
    });
    connect(m_tree, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem* item, int column) {
        if (m_quiet || column != 0 || !item->data(0, kIsChannelRole).toBool())
            return;
        emit channelToggled(currentPlot(), keyOf(item), item->checkState(0) == Qt::Checked);
    });
}

QTreeWidgetItem* ChannelPicker::instrumentItem(int instrument)
{
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i)
        if (m_tree->topLevelItem(i)->data(0, kInstrumentRole).toInt() == instrument)
            return m_tree->topLevelItem(i);
    int at = 0;
    while (at < m_tree->topLevelItemCount() && m_tree->topLevelItem(at)->data(0, kInstrumentRole).toInt() < instrument)
        ++at;
    auto* item = new QTreeWidgetItem;
    item->setData(0, kInstrumentRole, instrument);
    item->setFlags(Qt::ItemIsEnabled);
    m_tree->insertTopLevelItem(at, item);
    item->setExpanded(true);
    return item;
}

void ChannelPicker::setInstrumentChannels(int instrument, const QString& instrumentName, const QVector<Entry>& channels)
{
    ++m_quiet;
    QTreeWidgetItem* top = instrumentItem(instrument);
    top->setText(0, instrumentName);
    bool same = top->childCount() == channels.size();
    for (int i = 0; same && i < channels.size(); ++i)
        same = top->child(i)->data(0, kKeyRole).toInt() == channelId(channels[i].key)
            && top->child(i)->text(0) == channels[i].name;
    if (!same) {
        QSet<int> ticked;
        for (int i = 0; i < top->childCount(); ++i)
            if (top->child(i)->checkState(0) == Qt::Checked)
                ticked.insert(top->child(i)->data(0, kKeyRole).toInt());
        qDeleteAll(top->takeChildren());
        for (const Entry& e : channels) {
            auto* item = new QTreeWidgetItem(top);
            item->setText(0, e.name);
            item->setText(1, e.unit);
            item->setData(0, kKeyRole, channelId(e.key));
            item->setData(0, kInstrumentRole, instrument);
            item->setData(0, kIsChannelRole, true);
            item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
            item->setCheckState(0, ticked.contains(channelId(e.key)) ? Qt::Checked : Qt::Unchecked);
        }
        top->setExpanded(true);
    }
    top->setHidden(channels.isEmpty());
    --m_quiet;
}

int ChannelPicker::channelCount(int instrument) const
{
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i)
        if (m_tree->topLevelItem(i)->data(0, kInstrumentRole).toInt() == instrument)
            return m_tree->topLevelItem(i)->childCount();
    return 0;
}

void ChannelPicker::setPlotCount(int count)
{
    ++m_quiet;
    const int keep = m_plot->currentIndex();
    while (m_plot->count() > count)
        m_plot->removeItem(m_plot->count() - 1);
    while (m_plot->count() < count)
        m_plot->addItem(tr("Plot %1").arg(m_plot->count() + 1));
    m_plot->setCurrentIndex(std::clamp(keep, 0, count - 1));
    --m_quiet;
}

int ChannelPicker::plotCount() const { return m_plot->count(); }

void ChannelPicker::setCurrentPlot(int index)
{
    ++m_quiet;
    m_plot->setCurrentIndex(index);
    --m_quiet;
}

int ChannelPicker::currentPlot() const { return m_plot->currentIndex(); }

QTreeWidgetItem* ChannelPicker::itemFor(const dev::tele::ChannelKey& key) const
{
    const int id = channelId(key);
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i) {
        QTreeWidgetItem* top = m_tree->topLevelItem(i);
        for (int c = 0; c < top->childCount(); ++c)
            if (top->child(c)->data(0, kKeyRole).toInt() == id)
                return top->child(c);
    }
    return nullptr;
}

void ChannelPicker::showChecked(const QVector<dev::tele::ChannelKey>& channels)
{
    QSet<int> ids;
    for (const auto& k : channels)
        ids.insert(channelId(k));
    ++m_quiet;
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i) {
        QTreeWidgetItem* top = m_tree->topLevelItem(i);
        for (int c = 0; c < top->childCount(); ++c) {
            QTreeWidgetItem* item = top->child(c);
            const Qt::CheckState want = ids.contains(item->data(0, kKeyRole).toInt()) ? Qt::Checked : Qt::Unchecked;
            if (item->checkState(0) != want)
                item->setCheckState(0, want);
        }
    }
    --m_quiet;
}

void ChannelPicker::revealChecked()
{
    QList<QTreeWidgetItem*> withTicks;
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i) {
        QTreeWidgetItem* top = m_tree->topLevelItem(i);
        for (int c = 0; c < top->childCount(); ++c)
            if (top->child(c)->checkState(0) == Qt::Checked) {
                withTicks << top;
                break;
            }
    }
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i)
        m_tree->topLevelItem(i)->setExpanded(withTicks.isEmpty() || withTicks.contains(m_tree->topLevelItem(i)));
}

bool ChannelPicker::isChecked(const dev::tele::ChannelKey& key) const
{
    const QTreeWidgetItem* item = itemFor(key);
    return item && item->checkState(0) == Qt::Checked;
}

bool ChannelPicker::setChecked(const dev::tele::ChannelKey& key, bool on)
{
    QTreeWidgetItem* item = itemFor(key);
    if (!item)
        return false;
    item->setCheckState(0, on ? Qt::Checked : Qt::Unchecked);  // itemChanged → channelToggled
    return true;
}

} // namespace ui
