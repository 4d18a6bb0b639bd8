#include "widgets/plot_export.h"

#include "widgets/plot_stack.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QSaveFile>

#include <cmath>
#include <limits>
#include <vector>

namespace ui {
namespace {

QString trExport(const char* text) { return QCoreApplication::translate("ui::PlotExport", text); }

QByteArray csvField(const QString& s)
{
    QByteArray b = s.toUtf8();
    if (b.contains(',') || b.contains('"') || b.contains('\n')) {
        b.replace("\"", "\"\"");
        b = '"' + b + '"';
    }
    return b;
}

struct Column {
    dev::tele::ChannelKey key;
    const dev::tele::ChannelStore* store = nullptr;
    double anchorS = 0;
    std::size_t next = 0, end = 0;  ///< raw samples [next, end) still to write
};

bool ensureDir(const QString& path, QString* error)
{
    const QDir dir = QFileInfo(path).absoluteDir();
    if (dir.exists() || dir.mkpath(QStringLiteral(".")))
        return true;
    if (error)
        *error = trExport("Cannot create the folder %1.").arg(dir.absolutePath());
    return false;
}

} // namespace

CsvExportResult exportCsv(const PlotStack& stack, const QString& path, qint64 rawLimitSamples)
{
    CsvExportResult result;
    const PlotDataSource* source = stack.source();
    if (!source) {
        result.error = trExport("Nothing to export: the plots have no data source.");
        return result;
    }
    const QCPRange range = stack.timeRange();
    std::vector<Column> cols;
    qint64 total = 0;
    for (const dev::tele::ChannelKey& key : stack.allChannels()) {
        Column c;
        c.key = key;
        c.store = source->store(key);
        c.anchorS = stack.anchorS(key.instrument);
        if (c.store && !c.store->empty() && !std::isnan(c.anchorS)) {
            c.next = c.store->lowerBound(c.anchorS + range.lower);
            // The newest sample sits exactly at x = 0 in a live view: include the range's end.
            c.end = c.store->lowerBound(std::nextafter(c.anchorS + range.upper, std::numeric_limits<double>::infinity()));
            total += static_cast<qint64>(c.end - c.next);
        }
        cols.push_back(c);
    }
    if (cols.empty()) {
        result.error = trExport("Nothing to export: no plot has a channel.");
        return result;
    }
    if (!ensureDir(path, &result.error))
        return result;
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text)) {
        result.error = trExport("Cannot write %1: %2").arg(QDir::toNativeSeparators(path), file.errorString());
        return result;
    }
    result.decimated = total > rawLimitSamples;
    QByteArray out;
    out.reserve(1 << 16);
    auto flush = [&] {
        if (out.size() > (1 << 16) - 512) {
            file.write(out);
            out.clear();
        }
    };
    out += "# BenchPilot plot export: ";
    out += result.decimated
        ? QByteArray("decimated view (") + QByteArray::number(total)
            + " samples in range; each pixel column gives two rows: the minimum, then the maximum of every channel)\n"
        : QByteArray("raw samples (every stored sample in the visible range)\n");
    out += "# time range " + QByteArray::number(range.lower, 'f', 6) + " .. " + QByteArray::number(range.upper, 'f', 6)
        + " s relative to each instrument's anchor\n";
    for (int i = 0; i < 2; ++i)
        if (!std::isnan(stack.anchorS(i)))
            out += "# anchor " + csvField(source->instrumentName(i)) + " = " + QByteArray::number(stack.anchorS(i), 'f', 6)
                + " s device time\n";
    out += "time_s,instrument";
    for (const Column& c : cols) {
        const QString unit = source->channelUnit(c.key);
        out += ',' + csvField(unit.isEmpty() ? source->channelName(c.key) : QStringLiteral("%1 [%2]").arg(source->channelName(c.key), unit));
    }
    out += '\n';

    if (!result.decimated) {
        // Merge the channels by time: a row is one sample time of one instrument.
        for (;;) {
            int first = -1;
            double x = 0;
            for (int i = 0; i < int(cols.size()); ++i) {
                const Column& c = cols[std::size_t(i)];
                if (c.next >= c.end)
                    continue;
                const double xi = c.store->at(c.next).tS - c.anchorS;
                if (first < 0 || xi < x) {
                    first = i;
                    x = xi;
                }
            }
            if (first < 0)
                break;
            const Column& lead = cols[std::size_t(first)];
            const double t = lead.store->at(lead.next).tS;
            out += QByteArray::number(x, 'f', 6) + ',' + csvField(source->instrumentName(lead.key.instrument));
            for (Column& c : cols) {
                out += ',';
                // Same sample time within 0.1 µs (the device clock ticks in ≥ 100 µs; stores
                // that started at different samples may round a time differently).
                if (c.next < c.end && c.key.instrument == lead.key.instrument && std::abs(c.store->at(c.next).tS - t) < 1e-7)
                    out += QByteArray::number(c.store->at(c.next++).value, 'g', 9);
            }
            out += '\n';
            ++result.rows;
            flush();
        }
    } else {
        const int columns = std::max(1, stack.columns());
        std::vector<std::vector<dev::tele::MinMax>> mm(cols.size(), std::vector<dev::tele::MinMax>(std::size_t(columns)));
        for (std::size_t i = 0; i < cols.size(); ++i)
            if (cols[i].store && !cols[i].store->empty() && !std::isnan(cols[i].anchorS))
                cols[i].store->decimate(cols[i].anchorS + range.lower, cols[i].anchorS + range.upper, columns, mm[i].data());
        const double width = range.size() / columns;
        for (int col = 0; col < columns; ++col) {
            bool any = false;
            for (const auto& m : mm)
                any = any || !m[std::size_t(col)].empty();
            if (!any)
                continue;
            for (int which = 0; which < 2; ++which) {
                out += QByteArray::number(range.lower + (col + 0.5) * width, 'f', 6) + ',';
                for (const auto& m : mm) {
                    out += ',';
                    const dev::tele::MinMax& v = m[std::size_t(col)];
                    if (!v.empty())
                        out += QByteArray::number(which == 0 ? v.min : v.max, 'g', 9);
                }
                out += '\n';
                ++result.rows;
            }
            flush();
        }
    }
    file.write(out);
    if (!file.commit()) {
        result.error = trExport("Cannot write %1: %2").arg(QDir::toNativeSeparators(path), file.errorString());
        return result;
    }
    result.ok = true;
    return result;
}

bool exportPng(PlotStack& stack, const QString& path, QString* error, int width, int height)
{
    if (!ensureDir(path, error))
        return false;
    if (stack.savePng(path, width, height))
        return true;
    if (error)
        *error = trExport("Cannot write the picture %1.").arg(QDir::toNativeSeparators(path));
    return false;
}

bool exportPdf(PlotStack& stack, const QString& path, QString* error)
{
    if (!ensureDir(path, error))
        return false;
    if (stack.savePdf(path))
        return true;
    if (error)
        *error = trExport("Cannot write the PDF %1.").arg(QDir::toNativeSeparators(path));
    return false;
}

} // namespace ui
