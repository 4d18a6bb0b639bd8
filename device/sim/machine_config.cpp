#include "device/sim/machine_config.h"

namespace dev::sim {

MachineConfig analyzerConfig()
{
    MachineConfig m;
    m.kind = dev::proto::DeviceKind::Analyzer;
    m.model = "BenchPilot analyzer manipulator (simulated)";
    m.profile = ProfileKind::SeedSCurve;
    m.zAfterXy = true;
    // XY: 8 mm lead, 200 steps × 16 microsteps; encoder 1000 lines × 4 on the same lead.
    AxisConfig x;
    x.letter = 'X';
    x.travel = 200;
    x.stepSize = 8.0 / 3200;
    x.resolution = 8.0 / 4000;
    x.maxSpeed = 100;
    x.defaultSpeed = 50;   // seed 000 Table 2 runs Y at 50 mm/s
    x.accelTimeS = 0.1;    // seed 000 Table 2
    x.maxAccel = 1500;
    x.physicalMaxAccel = 4000;
    x.backlash = 0.02;
    x.leadErrorPerUnit = 1.5e-4;
    // No periodic pitch error on the analyzer's screws: its lead error is their whole
    // pitch error (the encoder reads the carriage, so the readback sees it as a gauge
    // would). The stage's screw has the ripple.
    x.switchRepeatability = 0.01;
    x.startPosition = 57.3;
    AxisConfig y = x;
    y.letter = 'Y';
    y.maxAccel = 2000;
    y.leadErrorPerUnit = -1.0e-4;
    y.startPosition = 121.8;
    AxisConfig z = x;
    z.letter = 'Z';
    z.travel = 100;
    z.stepSize = 4.0 / 3200;
    z.resolution = 4.0 / 4000;
    z.maxSpeed = 50;
    z.defaultSpeed = 30;
    z.maxAccel = 800;
    z.physicalMaxAccel = 2500;
    z.homeFastSpeed = 15;
    z.backlash = 0.01;
    z.leadErrorPerUnit = 1.0e-4;
    z.startPosition = 33.0;
    // Plunger pump: 1000 µL over 48000 microsteps.
    AxisConfig p;
    p.letter = 'P';
    p.unit = dev::proto::AxisUnit::Microlitre;
    p.travel = 1000;
    p.stepSize = 1000.0 / 48000;
    p.resolution = 0.05;
    p.maxSpeed = 500;
    p.defaultSpeed = 100;
    p.accelTimeS = 0.05;
    p.maxAccel = 5000;
    p.physicalMaxAccel = 20000;
    p.homeFastSpeed = 200;
    p.homeSlowSpeed = 10;
    p.homeBackoff = 5;
    p.homeSwitchAt = -2;
    p.limitSwitchMargin = 2;
    p.hardStopMargin = 10;
    p.startPosition = 250;
    m.axes = {x, y, z, p};
    return m;
}

MachineConfig stageConfig()
{
    MachineConfig m;
    m.kind = dev::proto::DeviceKind::Stage;
    m.model = "BenchPilot microscope stage (simulated)";
    m.profile = ProfileKind::JerkLimited;
    m.closedLoop = true;
    // The rotor lags its steps by 0.8 ms before the screw turns; the table lags the
    // nut by 2 ms (driveLagS). With the rotor alone modelled as instant, the loop's
    // ultimate period was about three control periods, where no continuous-time
    // tuning rule (Ziegler–Nichols included) holds; see docs/tuning.md.
    m.rotorLagS = 0.0008;
    m.loop.velocityFeedForwardS = m.driveLagS + m.rotorLagS;
    m.loop.accelFeedForwardS2 = m.driveLagS * m.rotorLagS;
    // 1 mm lead ball screw, 200 steps × 16 microsteps; grating 2 µm pitch counted ×4.
    AxisConfig x;
    x.letter = 'X';
    x.travel = 100;
    x.stepSize = 1.0 / 3200;
    x.resolution = 0.0005;
    x.maxSpeed = 20;
    x.defaultSpeed = 10;
    x.maxAccel = 200;
    x.maxJerk = 4000;
    x.physicalMaxAccel = 1000;
    x.homeFastSpeed = 5;
    x.homeSlowSpeed = 0.5;
    x.homeBackoff = 0.5;
    x.backlash = 0.004;
    x.leadErrorPerUnit = 3.0e-4;
    // A ground screw's ripple once per turn: the grating loop takes it out.
    x.pitchErrorAmplitude = 0.002;
    x.pitchErrorPeriod = 1.0;
    // The grating itself: +5 µm per metre (0.5 µm over the travel); the loop puts
    // the carriage short by as much, which only a reference at the work point sees.
    x.scaleErrorPerUnit = 5e-6;
    // Seed 002's fitted error of the X axis (work point against the grating), µm over mm.
    x.abbeErrorPolyUm = {1.563, 0.9473, -0.0006};
    x.switchRepeatability = 0.001;
    x.startPosition = 41.7;
    AxisConfig y = x;
    y.letter = 'Y';
    y.leadErrorPerUnit = -2.0e-4;
    y.scaleErrorPerUnit = -4e-6;
    y.abbeErrorPolyUm = {1.021, 0.6397, 0.0168};
    y.startPosition = 63.2;
    m.axes = {x, y};
    return m;
}

} // namespace dev::sim
