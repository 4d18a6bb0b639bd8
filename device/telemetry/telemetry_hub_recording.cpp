// TelemetryHub: recording telemetry to a CSV file as batches arrive, buffered
// and flushed in the background (see docs/telemetry.md for the format).
#include "device/telemetry/telemetry_hub.h"
#include "device/telemetry/telemetry_hub_detail.h"

#include <QDir>
#include <QVarLengthArray>

#include <charconv>

namespace dev::tele {
namespace {
/// Device microseconds as seconds with six decimals, exactly.
void appendTimeUs(QByteArray& out, std::uint64_t us)
{
    char buf[40];
    auto r = std::to_chars(buf, buf + sizeof buf, us / 1000000);
    *r.ptr++ = '.';
    const auto frac = static_cast<unsigned>(us % 1000000);
    for (unsigned d = 100000; d > 0; d /= 10)
        *r.ptr++ = static_cast<char>('0' + (frac / d) % 10);
    out.append(buf, static_cast<qsizetype>(r.ptr - buf));
}
} // namespace

// ---- recording ------------------------------------------------------------------

bool TelemetryHub::startRecording(const QString& csvPath, const QVector<ChannelKey>& channels, motion::msg::Message* error)
{
    auto fail = [error](const motion::msg::Message& why) {
        if (error)
            *error = why;
        return false;
    };
    if (m_record)
        return fail(motion::msg::make("telemetry.already_recording", {motion::msg::verbatim("file", QDir::toNativeSeparators(m_record->file.fileName()).toStdString())}));
    QVector<ChannelKey> columns;
    for (const auto& k : channels)
        if (instrument(k.instrument) && !columns.contains(k))
            columns.push_back(k);
    if (columns.isEmpty())
        return fail(motion::msg::make("telemetry.nothing_to_record"));
    auto rec = std::make_unique<Recording>();
    rec->file.setFileName(csvPath);
    const auto cannotWrite = [&] {
        return motion::msg::make("file.cannot_write", {motion::msg::verbatim("file", QDir::toNativeSeparators(csvPath).toStdString()),
                                               motion::msg::verbatim("detail", rec->file.errorString().toStdString())});
    };
    if (!rec->file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text))
        return fail(cannotWrite());
    rec->columns = columns;
    rec->buffer.reserve(kRecordFlushBytes + 4096);
    QByteArray header = "time_s,instrument";
    for (const auto& k : columns) {
        const QString unit = channelUnit(k);
        header += ',' + csvCell(unit.isEmpty() ? channelName(k) : tr("%1 [%2]").arg(channelName(k), unit));
    }
    header += '\n';
    if (rec->file.write(header) != header.size() || !rec->file.flush())
        return fail(cannotWrite());
    m_record = std::move(rec);
    m_flushTimer.start();
    recomputeCollected();
    Want w;
    w.channels = columns;
    w.rateHz = 0;  // does not raise anyone's rate; see unionFor()
    m_wants.insert(kRecordingConsumer, w);
    scheduleApply();
    return true;
}

void TelemetryHub::stopRecording()
{
    if (!m_record)
        return;
    flushRecording();
    if (m_record) {
        m_record->file.close();
        m_record.reset();
    }
    m_flushTimer.stop();
    m_wants.remove(kRecordingConsumer);
    recomputeCollected();
    scheduleApply();
}

QString TelemetryHub::recordingPath() const { return m_record ? m_record->file.fileName() : QString(); }
quint64 TelemetryHub::recordedRows() const { return m_record ? m_record->rows : 0; }

void TelemetryHub::writeRecordRows(int index, const dev::proto::TelemetryBatch& batch)
{
    Recording& r = *m_record;
    const std::size_t nc = batch.channels.size();
    // Column → position of that channel in the batch (−1: not in it).
    QVarLengthArray<int, 32> pos(r.columns.size());
    bool any = false;
    for (int col = 0; col < r.columns.size(); ++col) {
        pos[col] = -1;
        if (r.columns[col].instrument != index)
            continue;
        for (std::size_t c = 0; c < nc; ++c)
            if (batch.channels[c] == r.columns[col].ref) {
                pos[col] = static_cast<int>(c);
                any = true;
            }
    }
    if (!any)
        return;
    const Instrument* in = instrument(index);
    const QByteArray who = csvCell(in ? in->name : QString::number(index));
    dev::Instrument* client = in ? in->client.data() : nullptr;
    for (std::size_t k = 0; k < batch.sampleCount; ++k) {
        appendTimeUs(r.buffer, batch.firstSampleTimeUs + k * batch.periodUs);
        r.buffer += ',';
        r.buffer += who;
        for (int col = 0; col < r.columns.size(); ++col) {
            r.buffer += ',';
            if (pos[col] < 0)
                continue;
            const dev::proto::ChannelRef ref = r.columns[col].ref;
            const std::int32_t raw = batch.values[k * nc + static_cast<std::size_t>(pos[col])];
            const double v = client ? client->toAxisUnits(ref, raw) : double(raw);
            appendShortest(r.buffer, v * unitFactor(r.columns[col]));
        }
        r.buffer += '\n';
        ++r.rows;
    }
    if (r.buffer.size() >= kRecordFlushBytes)
        flushRecording();
}

void TelemetryHub::flushRecording()
{
    if (!m_record || m_record->buffer.isEmpty())
        return;
    Recording& r = *m_record;
    const qint64 written = r.file.write(r.buffer);
    if (written != r.buffer.size() || !r.file.flush()) {
        failRecording(r.file.errorString());
        return;
    }
    r.buffer.resize(0);  // keeps its allocation (clear() would free it): no churn from one flush to the next
}

void TelemetryHub::failRecording(const QString& why)
{
    const QString path = QDir::toNativeSeparators(m_record->file.fileName());
    m_record->file.close();
    m_record.reset();
    m_flushTimer.stop();
    m_wants.remove(kRecordingConsumer);
    recomputeCollected();
    scheduleApply();
    emit problem(motion::msg::make("telemetry.recording_stopped", {motion::msg::verbatim("file", path.toStdString()), motion::msg::verbatim("detail", why.toStdString())}));
}

} // namespace dev::tele
