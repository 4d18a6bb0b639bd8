#pragma once
// Every text a window shows, read back as a person would read the screen: what widgets
// hold (labels, buttons, titles, items, headers, tooltips, placeholders), what plots draw
// (axis labels, tick labels, legends, titles) and what custom widgets paint themselves
// (the plate map, the stage map, the travel view), caught from their paint calls.
#include <QAbstractButton>
#include <QAbstractItemView>
#include <QComboBox>
#include <QDockWidget>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenuBar>
#include <QPaintDevice>
#include <QPaintEngine>
#include <QProgressBar>
#include <QRegularExpression>
#include <QTabBar>
#include <QTabWidget>
#include <QTableWidget>
#include <QTextItem>
#include <QTreeWidget>

#include <qcustomplot.h>

namespace guitest {

/// A paint device that keeps the text drawn on it and nothing else.
class TextCatcher final : public QPaintDevice {
public:
    explicit TextCatcher(QSize size) : m_size(size) {}
    ~TextCatcher() override = default;
    QPaintEngine* paintEngine() const override { return &m_engine; }
    const QStringList& texts() const { return m_engine.texts; }

protected:
    int metric(PaintDeviceMetric m) const override
    {
        switch (m) {
        case PdmWidth: return m_size.width();
        case PdmHeight: return m_size.height();
        case PdmWidthMM: return m_size.width() * 254 / 960;
        case PdmHeightMM: return m_size.height() * 254 / 960;
        case PdmNumColors: return 0x7fffffff;
        case PdmDepth: return 32;
        case PdmDpiX:
        case PdmDpiY:
        case PdmPhysicalDpiX:
        case PdmPhysicalDpiY: return 96;
        case PdmDevicePixelRatio: return 1;
        case PdmDevicePixelRatioScaled: return static_cast<int>(devicePixelRatioFScale());
        default: return 0;
        }
    }

private:
    class Engine final : public QPaintEngine {
    public:
        Engine() : QPaintEngine(QPaintEngine::AllFeatures) {}
        bool begin(QPaintDevice*) override { return true; }
        bool end() override { return true; }
        void updateState(const QPaintEngineState&) override {}
        void drawPixmap(const QRectF&, const QPixmap&, const QRectF&) override {}
        void drawPolygon(const QPointF*, int, PolygonDrawMode) override {}
        void drawPath(const QPainterPath&) override {}
        void drawTextItem(const QPointF&, const QTextItem& item) override { texts << item.text(); }
        Type type() const override { return QPaintEngine::User; }
        QStringList texts;
    };
    QSize m_size;
    mutable Engine m_engine;
};

/// The text `w` paints itself (not its children's).
inline QStringList paintedText(QWidget* w)
{
    TextCatcher catcher(w->size().expandedTo(QSize(1, 1)));
    w->render(&catcher, QPoint(), QRegion(), QWidget::RenderFlags());
    return catcher.texts();
}

/// Calls `check(where, text)` for every text a plot draws: axis and tick labels, legend
/// entries, title and text items.
template <typename Check>
void forEachPlotText(QCustomPlot* plot, const QString& name, Check check)
{
    for (QCPAxisRect* rect : plot->axisRects())
        for (QCPAxis* axis : rect->axes()) {
            if (!axis->visible())
                continue;
            check(name + QStringLiteral(" axis label"), axis->label());
            if (axis->tickLabels())
                for (const QString& t : axis->tickVectorLabels())
                    check(name + QStringLiteral(" tick label"), t);
        }
    // Legends sit in the plot's layout or in an axis rect's inset layout (one per panel).
    QList<QCPLayoutElement*> elements = plot->plotLayout()->elements(true);
    for (QCPAxisRect* rect : plot->axisRects())
        elements += rect->insetLayout()->elements(true);
    for (QCPLayoutElement* e : elements) {
        if (auto* legend = qobject_cast<QCPLegend*>(e); legend && legend->visible())
            for (int i = 0; i < legend->itemCount(); ++i)
                if (auto* p = qobject_cast<QCPPlottableLegendItem*>(legend->item(i)))
                    check(name + QStringLiteral(" legend"), p->plottable()->name());
        if (auto* t = qobject_cast<QCPTextElement*>(e); t && t->visible())
            check(name + QStringLiteral(" title"), t->text());
    }
    for (int i = 0; i < plot->itemCount(); ++i)
        if (auto* t = qobject_cast<QCPItemText*>(plot->item(i)); t && t->visible())
            check(name + QStringLiteral(" text"), t->text());
}

/// Calls `check(where, text)` for every text `root` and its visible children show.
template <typename Check>
void forEachShownText(QWidget* root, Check check, bool painted = false)
{
    QList<QWidget*> all = root->findChildren<QWidget*>();
    all.prepend(root);
    for (QWidget* w : all) {
        if (!w->isVisibleTo(root->window()))
            continue;
        const QString name = QString::fromLatin1(w->metaObject()->className());
        check(name + QStringLiteral(" tooltip"), w->toolTip());
        if (auto* l = qobject_cast<QLabel*>(w))
            check(name, l->text());
        if (auto* b = qobject_cast<QAbstractButton*>(w))
            check(name, b->text());
        if (auto* g = qobject_cast<QGroupBox*>(w))
            check(name, g->title());
        if (auto* p = qobject_cast<QProgressBar*>(w); p && p->isTextVisible())
            check(name, p->text());
        if (auto* d = qobject_cast<QDockWidget*>(w))
            check(name, d->windowTitle());
        if (auto* e = qobject_cast<QLineEdit*>(w))
            check(name + QStringLiteral(" placeholder"), e->placeholderText());
        if (auto* c = qobject_cast<QComboBox*>(w))
            for (int i = 0; i < c->count(); ++i)
                check(name, c->itemText(i));
        if (auto* t = qobject_cast<QTabWidget*>(w))
            for (int i = 0; i < t->count(); ++i)
                check(name, t->tabText(i));
        if (auto* t = qobject_cast<QTabBar*>(w))
            for (int i = 0; i < t->count(); ++i)
                check(name, t->tabText(i));
        if (auto* m = qobject_cast<QMenuBar*>(w))
            for (QAction* a : m->actions())
                check(name, a->text());
        if (auto* v = qobject_cast<QAbstractItemView*>(w); v && v->model()) {
            QAbstractItemModel* model = v->model();
            for (int c = 0; c < model->columnCount(); ++c)
                check(name + QStringLiteral(" header"), model->headerData(c, Qt::Horizontal).toString());
            // The items' own words: what the rows say, read from the model.
            for (int r = 0; r < std::min(model->rowCount(), 200); ++r)
                for (int c = 0; c < model->columnCount(); ++c) {
                    const QModelIndex i = model->index(r, c);
                    check(name + QStringLiteral(" item"), model->data(i).toString());
                    check(name + QStringLiteral(" item tooltip"), model->data(i, Qt::ToolTipRole).toString());
                }
        }
        if (auto* p = qobject_cast<QCustomPlot*>(w)) {
            forEachPlotText(p, name, check);
            continue;  // drawn from its buffers: read above
        }
        // Widgets that paint words themselves (maps, views, lamps): their paint calls.
        if (painted && name.startsWith(QLatin1String("ui::")))
            for (const QString& t : paintedText(w))
                check(name + QStringLiteral(" painted"), t);
    }
}

/// The Latin words of `text` that a person reading Chinese would read as English: every
/// word of two letters or more, except proper names, units, key names, symbols and
/// abbreviations of up to five capitals (PID, CSV, ISO).
inline QStringList englishWords(const QString& text)
{
    static const QStringList kNames = {
        // products, programs, formats, people
        QStringLiteral("BenchPilot"), QStringLiteral("benchpilot"), QStringLiteral("GRBL"), QStringLiteral("Grbl"),
        QStringLiteral("grblHAL"), QStringLiteral("Fiji"), QStringLiteral("ImageJ"), QStringLiteral("Micro"),
        QStringLiteral("Manager"), QStringLiteral("Opentrons"), QStringLiteral("LinuxCNC"), QStringLiteral("Ziegler"),
        QStringLiteral("Nichols"), QStringLiteral("Tyreus"), QStringLiteral("Luyben"), QStringLiteral("Pessen"),
        QStringLiteral("TileConfiguration"), QStringLiteral("Python"), QStringLiteral("Qt"),
        // a camera source's forms, typed as they are in any language (sim, uvc:NAME, command:CMD, folder:DIR)
        QStringLiteral("sim"), QStringLiteral("uvc"), QStringLiteral("command"), QStringLiteral("folder"),
        // keys
        QStringLiteral("Esc"), QStringLiteral("Ctrl"), QStringLiteral("Shift"), QStringLiteral("PgUp"), QStringLiteral("PgDn"),
        QStringLiteral("Enter"), QStringLiteral("Tab"), QStringLiteral("Alt"),
        // units
        QStringLiteral("mm"), QStringLiteral("um"), QStringLiteral("mL"), QStringLiteral("ms"), QStringLiteral("Hz"),
        QStringLiteral("kHz"), QStringLiteral("MHz"), QStringLiteral("Bd"), QStringLiteral("rpm"), QStringLiteral("px"), QStringLiteral("nm"),
        QStringLiteral("min"), QStringLiteral("dB"), QStringLiteral("us"),
        // symbols of control and statistics
        QStringLiteral("Kp"), QStringLiteral("Ki"), QStringLiteral("Kd"), QStringLiteral("Ku"), QStringLiteral("Tu"),
        QStringLiteral("Ti"), QStringLiteral("Td"), QStringLiteral("kp"), QStringLiteral("ki"), QStringLiteral("kd"),
        QStringLiteral("Xc"), QStringLiteral("Yc"), QStringLiteral("sin"), QStringLiteral("cos"), QStringLiteral("adj"),
    };
    // Markup, and command-line options (--camera-socket): those are typed as they are in any language.
    static const QRegularExpression markup(QStringLiteral("<[^>]*>|&[a-z]+;|&#\\d+;|--[a-z][a-z0-9-]*"));
    static const QRegularExpression word(QStringLiteral("[A-Za-z]{2,}"));
    QString t = text;
    t.remove(markup);
    QStringList out;
    for (auto m = word.globalMatch(t); m.hasNext();) {
        const QString w = m.next().captured(0);
        const bool abbreviation = w == w.toUpper() && w.size() <= 5;
        if (!abbreviation && !kNames.contains(w))
            out << w;
    }
    return out;
}

} // namespace guitest
