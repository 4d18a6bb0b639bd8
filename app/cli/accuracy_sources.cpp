#include "accuracy_sources.h"

#include "accuracy_cli.h"
#include "camera_cli.h"
#include "cli_session.h"
#include "device/camera/scale_reading_source.h"
#include "device/files/accuracy/scale_certificate_csv.h"
#include "device/jobs/accuracy/gauge_source.h"
#include "device/jobs/accuracy/interferometer_source.h"
#include "device/jobs/accuracy/manual_source.h"
#include "device/jobs/accuracy/readback_source.h"
#include "device/link/gauge_dialect.h"
#include "device/link/serial_transport.h"
#include "device/link/simulated_gauge.h"
#include "device/link/simulated_link.h"
#include "widgets/wording/wording.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <QSocketNotifier>

#include <cmath>
#include <unistd.h>

namespace app::cli {
namespace {
QString tr(const char* text) { return QCoreApplication::translate("app::cli", text); }

/// A typed reading: a number, with an optional unit (mm when none).
std::optional<double> parseTyped(const QString& word)
{
    const QString w = word.trimmed();
    if (w.isEmpty())
        return std::nullopt;
    // With a unit: the gauge dialect's rules; without: millimetres.
    const auto a = dev::gaugewire::parseAnswer(w.toStdString(), "stdin");
    if (a.valueMm)
        return a.valueMm;
    bool ok = false;
    const double v = w.toDouble(&ok);  // QString::toDouble reads the C locale's '.'
    if (ok && std::isfinite(v))
        return v;
    return std::nullopt;
}
} // namespace

ReadingSource* makeSource(Invocation& inv, CliSession& session, const QString& spec, int axis, QObject* owner)
{
    if (spec == QLatin1String("readback"))
        return new dev::jobs::ReadbackSource(session.instrument(), owner);
    if (spec == QLatin1String("manual")) {
        // Readings are typed on standard input; the GUI's has nobody at it.
        if (inv.host().insideGui()) {
            inv.usage(tr("--source manual reads what a person types at benchpilot-cli; in the GUI use the Calibration screen"));
            return nullptr;
        }
        return new dev::jobs::ManualSource(owner);
    }
    if (spec == QLatin1String("interferometer"))
        return new dev::jobs::InterferometerSource(owner);
    if (spec == QLatin1String("camera") || spec.startsWith(QLatin1String("camera:"))) {
        // The glass line scales are what the simulated camera looks at unless --specimen says otherwise.
        auto camera = cameraFor(inv, &session, spec.size() > 7 ? spec.mid(7) : QStringLiteral("sim"), "line-scales");
        if (!camera)
            return nullptr;
        camera->setParent(owner);
        dev::camera::ScaleReadingOptions options;
        if (inv.isSet(QStringLiteral("certificate"))) {
            // Checked against the scale it is for: its graduations on the scale's pitch,
            // within its length.
            dev::files::accuracy::ScaleGeometry scale;
            scale.pitchMm = options.graduationMm;
            if (!inv.number(QStringLiteral("scale-length"), scale.lengthMm, scale.lengthMm))
                return nullptr;
            const auto read = dev::files::accuracy::loadScaleCertificateFile(inv.path(inv.value(QStringLiteral("certificate"))), scale);
            if (reportProblems(inv, read.problems()) || !read.ok())
                return nullptr;
            options.certificate = *read;
        }
        return new dev::camera::ScaleReadingSource(camera.release(), options, owner);
    }
    if (!spec.startsWith(QLatin1String("gauge:")) || spec.size() <= 6) {
        inv.usage(tr("--source '%1': readback, gauge:PATH, manual, interferometer or camera[:SOURCE]").arg(spec));
        return nullptr;
    }
    const QString port = spec.mid(6);
    double timeoutS = 1;
    if (!inv.number(QStringLiteral("gauge-timeout"), timeoutS, 1.0))
        return nullptr;
    if (!(timeoutS > 0 && timeoutS <= 60)) {
        inv.usage(tr("--gauge-timeout must be from 0 to 60 s"));
        return nullptr;
    }
    dev::jobs::GaugeSource* source = nullptr;
    if (port == QLatin1String("sim")) {
        auto* link = qobject_cast<dev::SimulatedLink*>(session.link());
        if (!link) {
            // Inside the GUI the session never hands out the GUI's link (its clock and
            // machine are the screens'); its Calibration screen offers the simulated gauge.
            inv.usage(inv.host().insideGui() ? tr("--source gauge:sim is benchpilot-cli's own simulator's gauge: inside the GUI give the "
                                                  "gauge's port, or use the Calibration screen's simulated gauge")
                                             : tr("--source gauge:sim reads the in-process simulator's gauge: use it with --sim"));
            return nullptr;
        }
        auto* gauge = new dev::SimulatedGauge(link->machine(), axis, {}, owner);
        source = new dev::jobs::GaugeSource(gauge->hostEnd(), tr("simulated gauge"), owner);
    } else {
        double baud = 9600;
        if (!inv.number(QStringLiteral("gauge-baud"), baud, 9600.0))
            return nullptr;
        auto* serial = new dev::SerialTransport(port, static_cast<qint32>(baud), owner);
        source = new dev::jobs::GaugeSource(serial, port, owner);
    }
    source->link().setTimeoutMs(static_cast<int>(std::lround(timeoutS * 1000)));
    return source;
}

void attachStdinPrompter(Invocation& inv, dev::jobs::ReadingSource* source, const std::function<void()>& onQuit)
{
    auto* manual = qobject_cast<dev::jobs::ManualSource*>(source);
    if (!manual)
        return;
    struct Stdin {
        QByteArray buffer;
        bool closed = false;
        QSocketNotifier* notifier = nullptr;
    };
    auto in = std::make_shared<Stdin>();
    in->notifier = new QSocketNotifier(STDIN_FILENO, QSocketNotifier::Read, manual);
    QTextStream* err = &inv.err();
    auto prompt = [err](const dev::jobs::StopContext& s) {
        QString what;
        for (std::size_t n = 0; n < s.letters.size(); ++n)
            what += QStringLiteral("%1 %2 mm  ").arg(s.letters[n]).arg(s.targetsMm[n], 0, 'f', 3);
        *err << tr("reading %1 of %2: %3%4, cycle %5; type the reading in mm (q aborts): ")
                    .arg(s.index + 1)
                    .arg(s.total)
                    .arg(what, ui::words::term(motion::metrology::directionTermId(s.direction)))
                    .arg(s.cycle);
        err->flush();
    };
    // Lines typed ahead (or piped in) wait in the buffer for the stop they belong to.
    auto process = [manual, in, err, prompt, onQuit] {
        while (manual->waiting()) {
            const int nl = in->buffer.indexOf('\n');
            if (nl < 0) {
                if (in->closed) {
                    onQuit();  // stdin ended: nobody will type the rest
                    return;
                }
                return;
            }
            const QString line = QString::fromUtf8(in->buffer.left(nl)).trimmed();
            in->buffer.remove(0, nl + 1);
            if (line.isEmpty())
                continue;
            if (line == QLatin1String("q") || line == QLatin1String("quit") || line == QLatin1String("abort")) {
                onQuit();
                return;
            }
            std::vector<double> values;
            bool ok = true;
            for (const QString& word : line.split(QRegularExpression(QStringLiteral("[\\s;]+(?=[+\\-0-9.])")), Qt::SkipEmptyParts)) {
                if (const auto v = parseTyped(word))
                    values.push_back(*v);
                else
                    ok = false;
            }
            const dev::jobs::StopContext stop = *manual->waiting();
            if (!ok || !manual->provide(values)) {
                *err << tr("'%1' is not a reading here; ").arg(line);
                prompt(stop);
            }
        }
    };
    QObject::connect(manual, &dev::jobs::ManualSource::entryWanted, manual, [prompt, process](const dev::jobs::StopContext& s) {
        prompt(s);
        process();
    });
    QObject::connect(in->notifier, &QSocketNotifier::activated, manual, [in, process] {
        char chunk[256];
        const ssize_t n = ::read(STDIN_FILENO, chunk, sizeof chunk);
        if (n <= 0) {
            in->closed = true;
            in->notifier->setEnabled(false);
        } else {
            in->buffer.append(chunk, static_cast<int>(n));
        }
        process();
    });
}

} // namespace app::cli
