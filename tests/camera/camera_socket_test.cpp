// The camera sim:PATH against the server benchpilot-sim runs (both in this process, on a
// socket in a private folder): a capture is rendered where the stage is after the request,
// pixel for pixel what the in-process camera renders there; the live view asks for one frame
// at a time; no server, a server gone, garbage and silence each fail with their reason; the
// server refuses a path in use and replaces a stale socket.
#include "device/camera/camera_source.h"
#include "device/camera/sim_camera_server.h"
#include "device/camera/sim_socket_camera.h"

#include "integration/wait.h"
#include "motion/message_print.h"

#include <QFile>
#include <QLocalServer>
#include <QLocalSocket>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstring>
#include <memory>

using itest::waitFor;
namespace cam = dev::camera;

namespace {

/// A stage the test moves by hand, and how often the server looked at it.
struct FakeStage {
    double xMm = 10, yMm = 20;
    int reads = 0;
    cam::WorkPointSource source()
    {
        return [this]() -> std::optional<cam::WorkPoint> {
            ++reads;
            return cam::WorkPoint{xMm, yMm, std::uint64_t(1000)};
        };
    }
};

cam::SimCameraSettings smallCamera()
{
    cam::SimCameraSettings s;
    s.seed = 5;
    s.geometry.sensorWidthPx = s.geometry.sensorHeightPx = 64;
    s.geometry.pixelUm = 1;
    return s;
}

/// What a camera said, by request id.
struct Heard {
    explicit Heard(cam::Camera* c)
    {
        QObject::connect(c, &cam::Camera::opened, [this] { ++opened; });
        QObject::connect(c, &cam::Camera::captured, [this](std::uint64_t id, const cam::Frame& f) { frames[id] = f; });
        QObject::connect(c, &cam::Camera::failed, [this](std::uint64_t id, const motion::msg::Problem& p) { failures[id] = p.message; });
        QObject::connect(c, &cam::Camera::liveFrame, [this](const cam::Frame&) { ++live; });
    }
    bool answered(std::uint64_t id) const { return frames.count(id) || failures.count(id); }
    int opened = 0;
    int live = 0;
    std::map<std::uint64_t, cam::Frame> frames;
    std::map<std::uint64_t, motion::msg::Message> failures;
};

cam::CaptureRequest request(std::uint64_t id)
{
    cam::CaptureRequest r;
    r.id = id;
    return r;
}

/// A server of our own making that says what the test wants (or nothing), for the failures.
struct RawServer {
    explicit RawServer(const QString& path)
    {
        server.listen(path);
        QObject::connect(&server, &QLocalServer::newConnection, [this] {
            socket = server.nextPendingConnection();
            QObject::connect(socket, &QLocalSocket::readyRead, [this] { received += socket->readAll(); });
            if (!greeting.empty())
                socket->write(greeting.data(), static_cast<qint64>(greeting.size()));
        });
    }
    QLocalServer server;
    QLocalSocket* socket = nullptr;
    std::string greeting;
    QByteArray received;
};

std::string helloBytes()
{
    cam::SimWireHello h;
    h.specimen = "slide";
    return cam::encodeSimWire(h);
}

} // namespace

TEST(SimSocketCamera, ACaptureIsRenderedWhereTheStageIsAfterTheRequestAsTheInProcessCameraRendersIt)
{
    QTemporaryDir dir;
    FakeStage stage;
    cam::SimCameraServer server(stage.source(), smallCamera());
    motion::msg::Message error;
    const QString path = dir.filePath(QStringLiteral("cam"));
    ASSERT_TRUE(server.listen(path, &error)) << error;

    motion::msg::Message made;
    auto camera = cam::makeCamera("sim:" + path.toStdString(), {}, &made);
    ASSERT_TRUE(camera) << made;
    EXPECT_EQ(camera->source(), QStringLiteral("sim:") + path);
    Heard heard(camera.get());
    camera->open();
    camera->setExposureMs(3);
    cam::CaptureRequest r = request(7);
    cam::CameraGeometry g;
    g.sensorWidthPx = 96;
    g.sensorHeightPx = 80;
    g.pixelUm = 2;
    g.rotationDeg = 10;
    r.geometry = g;
    camera->capture(r);  // asked while opening: waits for the hello
    // The stage moves on after the call: the exposure starts after it, so the image shows this place.
    stage.xMm = 30.5;
    stage.yMm = 40.25;
    ASSERT_TRUE(waitFor([&] { return heard.answered(7); }, 20000));
    ASSERT_EQ(heard.failures.count(7), 0u) << heard.failures[7];
    EXPECT_EQ(heard.opened, 1);
    const cam::Frame& f = heard.frames[7];
    EXPECT_EQ(f.width, 96);
    EXPECT_EQ(f.height, 80);
    EXPECT_DOUBLE_EQ(f.exposureMs, 3);
    EXPECT_EQ(f.deviceTimeUs.value_or(0), 1000u);
    const cam::Specimen specimen(cam::SpecimenKind::Slide, 5);
    const cam::Frame there = cam::renderSimFrame(specimen, g, cam::SimOptics{}, 30.5, 40.25, 3, 5);
    EXPECT_TRUE(f.pixels == there.pixels) << "pixel for pixel the in-process camera's image at the stage's place";

    // Without a geometry: the server's own camera.
    camera->capture(request(8));
    ASSERT_TRUE(waitFor([&] { return heard.answered(8); }, 20000));
    EXPECT_EQ(heard.frames[8].width, 64);
    EXPECT_EQ(stage.reads, 2) << "the stage is read once a capture, when the request arrives";
}

TEST(SimSocketCamera, LiveAsksForOneFrameAtATimeSoASlowServerIsNeverQueuedFor)
{
    QTemporaryDir dir;
    RawServer raw(dir.filePath(QStringLiteral("cam")));
    raw.greeting = helloBytes();
    cam::SimSocketCamera camera(dir.filePath(QStringLiteral("cam")));
    Heard heard(&camera);
    camera.startLive();
    ASSERT_TRUE(waitFor([&] { return raw.received.count('\n') >= 1; }, 10000));
    itest::spin(300);  // ten live periods: a camera that queued would have asked again
    EXPECT_EQ(raw.received.count('\n'), 1) << raw.received.toStdString();
    // The answer comes: it is shown, and only then is the next frame asked for.
    cam::SimWireFrame f;
    f.id = 1;
    f.frame.width = f.frame.height = 2;
    f.frame.format = cam::PixelFormat::Grey8;
    f.frame.bitDepth = 8;
    f.frame.pixels = {1, 2, 3, 4};
    const std::string bytes = cam::encodeSimWire(f);
    raw.socket->write(bytes.data(), static_cast<qint64>(bytes.size()));
    ASSERT_TRUE(waitFor([&] { return heard.live == 1 && raw.received.count('\n') == 2; }, 10000)) << raw.received.toStdString();
    camera.stopLive();
}

TEST(SimSocketCamera, NoServerAtThePathFailsNamingIt)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("nobody"));
    cam::SimSocketCamera camera(path);
    Heard heard(&camera);
    camera.open();
    camera.capture(request(1));
    ASSERT_TRUE(waitFor([&] { return heard.answered(1); }, 10000));
    EXPECT_EQ(heard.failures[1].id, "camera.socket.no_server");
    EXPECT_EQ(heard.failures[1].text("socket"), path.toStdString());
    EXPECT_EQ(heard.failures[0].id, "camera.socket.no_server") << "the one who opened hears it too";
    EXPECT_FALSE(camera.isOpen());
}

TEST(SimSocketCamera, AServerGoneMidCaptureFailsItAndEveryLaterCapture)
{
    QTemporaryDir dir;
    FakeStage stage;
    auto server = std::make_unique<cam::SimCameraServer>(stage.source(), smallCamera());
    motion::msg::Message error;
    ASSERT_TRUE(server->listen(dir.filePath(QStringLiteral("cam")), &error)) << error;
    cam::SimSocketCamera camera(dir.filePath(QStringLiteral("cam")));
    Heard heard(&camera);
    camera.open();
    ASSERT_TRUE(waitFor([&] { return camera.isOpen(); }, 10000));
    camera.setExposureMs(20000);  // still exposing when the server goes
    camera.capture(request(1));
    ASSERT_TRUE(waitFor([&] { return stage.reads == 1; }, 10000));
    server.reset();
    EXPECT_FALSE(QFile::exists(dir.filePath(QStringLiteral("cam")))) << "the socket is removed with its server";
    ASSERT_TRUE(waitFor([&] { return heard.answered(1); }, 10000));
    EXPECT_EQ(heard.failures[1].id, "camera.socket.lost");
    EXPECT_FALSE(camera.isOpen());
    camera.capture(request(2));
    ASSERT_TRUE(heard.answered(2)) << "told at once";
    EXPECT_EQ(heard.failures[2].id, "camera.socket.lost");
}

TEST(SimSocketCamera, GarbageFromTheServerFailsWithTheReadersReason)
{
    QTemporaryDir dir;
    {
        RawServer raw(dir.filePath(QStringLiteral("a")));
        raw.greeting = "HTTP/1.1 200 OK\r\n\r\n";
        cam::SimSocketCamera camera(dir.filePath(QStringLiteral("a")));
        Heard heard(&camera);
        camera.open();
        ASSERT_TRUE(waitFor([&] { return heard.failures.count(0) > 0; }, 10000));
        EXPECT_EQ(heard.failures[0].id, "camera.socket.garbled");
        const auto* reason = heard.failures[0].arg("reason");
        ASSERT_TRUE(reason);
        EXPECT_EQ(std::get<std::shared_ptr<const motion::msg::Message>>(reason->value)->id, "camera.wire.not_json");
        EXPECT_EQ(heard.opened, 0);
    }
    {
        // A frame whose size is not its width × height: the capture fails, the link is dropped.
        RawServer raw(dir.filePath(QStringLiteral("b")));
        raw.greeting = helloBytes();
        cam::SimSocketCamera camera(dir.filePath(QStringLiteral("b")));
        Heard heard(&camera);
        camera.open();
        ASSERT_TRUE(waitFor([&] { return camera.isOpen(); }, 10000));
        camera.capture(request(4));
        ASSERT_TRUE(waitFor([&] { return !raw.received.isEmpty(); }, 10000));
        const std::string lie = R"({"schema":"benchpilot.sim-camera","version":1,"type":"frame","id":1,"width_px":4000,"height_px":4000,)"
                                R"("format":"grey16","bit_depth":16,"exposure_ms":1,"pixel_um":1,"sequence":0,"bytes":16})" "\n";
        raw.socket->write(lie.data(), static_cast<qint64>(lie.size()));
        ASSERT_TRUE(waitFor([&] { return heard.answered(4); }, 10000));
        EXPECT_EQ(heard.failures[4].id, "camera.socket.garbled");
        EXPECT_FALSE(camera.isOpen());
    }
}

TEST(SimSocketCamera, SilenceTimesOutTheHelloAndTheAnswer)
{
    QTemporaryDir dir;
    {
        RawServer raw(dir.filePath(QStringLiteral("mute")));  // accepts, never says hello
        cam::SimSocketCamera camera(dir.filePath(QStringLiteral("mute")));
        camera.setTimeoutsMs(200, 200);
        Heard heard(&camera);
        camera.open();
        camera.capture(request(1));
        ASSERT_TRUE(waitFor([&] { return heard.answered(1); }, 10000));
        EXPECT_EQ(heard.failures[1].id, "camera.socket.timeout");
    }
    {
        RawServer raw(dir.filePath(QStringLiteral("slow")));  // says hello, never answers
        raw.greeting = helloBytes();
        cam::SimSocketCamera camera(dir.filePath(QStringLiteral("slow")));
        camera.setTimeoutsMs(5000, 200);
        camera.setExposureMs(1);
        Heard heard(&camera);
        camera.open();
        camera.capture(request(2));
        ASSERT_TRUE(waitFor([&] { return heard.answered(2); }, 10000));
        EXPECT_EQ(heard.failures[2].id, "camera.socket.timeout");
        EXPECT_TRUE(camera.isOpen()) << "a late answer is dropped; the link stays";
    }
}

TEST(SimCameraServer, RefusesAPathInUseOrNotASocketAndReplacesAStaleOne)
{
    QTemporaryDir dir;
    FakeStage stage;
    const QString path = dir.filePath(QStringLiteral("cam"));
    cam::SimCameraServer first(stage.source(), smallCamera());
    motion::msg::Message error;
    ASSERT_TRUE(first.listen(path, &error)) << error;
    cam::SimCameraServer second(stage.source(), smallCamera());
    EXPECT_FALSE(second.listen(path, &error));
    EXPECT_EQ(error.id, "camera.socket.in_use");
    EXPECT_EQ(error.text("socket"), path.toStdString());
    first.close();
    EXPECT_FALSE(QFile::exists(path));

    // A socket left by a simulator that died: bound, never listened on, never removed.
    const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
    ASSERT_GE(fd, 0);
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    const QByteArray native = QFile::encodeName(path);
    std::memcpy(addr.sun_path, native.constData(), static_cast<std::size_t>(native.size()));
    ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
    ::close(fd);
    ASSERT_TRUE(QFile::exists(path));
    EXPECT_TRUE(second.listen(path, &error)) << error;
    second.close();

    QFile plain(dir.filePath(QStringLiteral("notes.txt")));
    ASSERT_TRUE(plain.open(QIODevice::WriteOnly));
    plain.write("keep me");
    plain.close();
    EXPECT_FALSE(second.listen(plain.fileName(), &error));
    EXPECT_EQ(error.id, "camera.socket.not_a_socket");
    EXPECT_TRUE(QFile::exists(plain.fileName()));
}

TEST(SimCameraServer, AnswersWhatItCannotReadWithAnErrorAndHangsUp)
{
    QTemporaryDir dir;
    FakeStage stage;
    cam::SimCameraServer server(stage.source(), smallCamera());
    motion::msg::Message error;
    ASSERT_TRUE(server.listen(dir.filePath(QStringLiteral("cam")), &error)) << error;
    QLocalSocket client;
    client.connectToServer(dir.filePath(QStringLiteral("cam")));
    ASSERT_TRUE(waitFor([&] { return client.state() == QLocalSocket::ConnectedState; }, 10000));
    QByteArray got;
    QObject::connect(&client, &QLocalSocket::readyRead, [&] { got += client.readAll(); });
    client.write("{\"schema\":\"benchpilot.sim-camera\",\"version\":1,\"type\":\"capture\",\"id\":1,\"exposure_ms\":1,\"camera\":{\"width_px\":99999}}\n");
    ASSERT_TRUE(waitFor([&] { return client.state() == QLocalSocket::UnconnectedState; }, 10000));
    got += client.readAll();
    const std::string text = got.toStdString();
    EXPECT_NE(text.find("\"type\":\"hello\""), std::string::npos) << text;
    EXPECT_NE(text.find("\"code\":\"bad_request\""), std::string::npos) << text;
    EXPECT_NE(text.find("camera.width_px"), std::string::npos) << "the detail names the field: " << text;
    EXPECT_EQ(stage.reads, 0) << "nothing rendered for it";
}
