<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>QObject</name>
    <message>
        <source>A well was interrupted</source>
        <translation>某个孔的加样被中断</translation>
    </message>
    <message>
        <source>The run stopped during &quot;%1&quot;, after its plunger move had been sent.

%2.

Skip counts the well as done; Do again repeats it in full.</source>
        <translation>运行在“%1”期间停止，此时其柱塞移动命令已发出。

%2。

“跳过”将该孔计为已完成；“重做”将其完整重做一遍。</translation>
    </message>
    <message>
        <source>Skip</source>
        <translation>跳过</translation>
    </message>
    <message>
        <source>Do again</source>
        <translation>重做</translation>
    </message>
    <message>
        <source>Confirm</source>
        <translation>确认</translation>
    </message>
    <message>
        <source>Tissue section, 2.5x overview</source>
        <translation>组织切片，2.5x 概览</translation>
    </message>
    <message>
        <source>Calibration</source>
        <translation>校准</translation>
    </message>
    <message>
        <source>&apos;sim&apos; is the in-process simulator&apos;s gauge: connect the instrument to the simulator first.</source>
        <translation>“sim”是进程内仿真器的测头：请先将仪器连接到仿真器。</translation>
    </message>
</context>
<context>
    <name>StepTexts</name>
    <message>
        <source>Aspirate</source>
        <translation>吸液</translation>
    </message>
    <message>
        <source>Dispense</source>
        <translation>排液</translation>
    </message>
    <message>
        <source>Mix</source>
        <translation>混匀</translation>
    </message>
    <message>
        <source>Wash</source>
        <translation>清洗</translation>
    </message>
    <message>
        <source>Air gap</source>
        <translation>空气间隔</translation>
    </message>
    <message>
        <source>Wait</source>
        <translation>等待</translation>
    </message>
    <message>
        <source>Touch off</source>
        <translation>贴壁</translation>
    </message>
    <message>
        <source>station %1</source>
        <translation>工位 %1</translation>
    </message>
    <message>
        <source>Aspirate %1 µL from %2</source>
        <translation>从 %2 吸液 %1 µL</translation>
    </message>
    <message>
        <source>Dispense %1 µL into %2</source>
        <translation>向 %2 排液 %1 µL</translation>
    </message>
    <message>
        <source>Mix %1 µL in %2</source>
        <translation>在 %2 中混匀 %1 µL</translation>
    </message>
    <message>
        <source>Wash %1 µL at %2</source>
        <translation>在 %2 清洗 %1 µL</translation>
    </message>
    <message>
        <source>Air gap %1 µL</source>
        <translation>空气间隔 %1 µL</translation>
    </message>
    <message>
        <source>Wait %1 s</source>
        <translation>等待 %1 s</translation>
    </message>
    <message>
        <source>Touch off in %1</source>
        <translation>在 %1 中贴壁</translation>
    </message>
    <message>
        <source>As written</source>
        <translation>按书写顺序</translation>
    </message>
    <message>
        <source>Column by column</source>
        <translation>逐列</translation>
    </message>
    <message>
        <source>Snake rows</source>
        <translation>行蛇形</translation>
    </message>
    <message>
        <source>Snake columns</source>
        <translation>列蛇形</translation>
    </message>
    <message>
        <source>Shortest</source>
        <translation>最短路径</translation>
    </message>
</context>
<context>
    <name>app::AboutDialog</name>
    <message>
        <source>Operator and test-bench application for laboratory motion instruments.</source>
        <translation>实验室运动仪器的操作与测试工作台软件。</translation>
    </message>
    <message>
        <source>Built with Qt %1, running on Qt %2.</source>
        <translation>基于 Qt %1 编译，运行于 Qt %2。</translation>
    </message>
    <message>
        <source>Copyright © 2026 The BenchPilot authors.</source>
        <translation>版权所有 © 2026 BenchPilot 作者。</translation>
    </message>
    <message>
        <source>BenchPilot is free software: you can redistribute it and modify it under the terms of the GNU General Public License, version 3 or (at your option) any later version (%1). It comes with NO WARRANTY, to the extent permitted by law. The full text: %2.</source>
        <translation>BenchPilot 是自由软件：您可以按照 GNU 通用公共许可证第 3 版或（由您选择）任何更新版本（%1）的条款再发布和修改它。在法律允许的范围内，本软件不提供任何担保（NO WARRANTY）。许可证全文：%2。</translation>
    </message>
    <message>
        <source>Libraries it is made of:</source>
        <translation>所用的库：</translation>
    </message>
    <message>
        <source>Library</source>
        <translation>库</translation>
    </message>
    <message>
        <source>Version</source>
        <translation>版本</translation>
    </message>
    <message>
        <source>Licence</source>
        <translation>许可证</translation>
    </message>
    <message>
        <source>About BenchPilot</source>
        <translation>关于 BenchPilot</translation>
    </message>
</context>
<context>
    <name>app::ApiControlStrip</name>
    <message>
        <source>Take back</source>
        <translation>收回控制权</translation>
    </message>
    <message>
        <source>End the script&apos;s control now: its next call is refused, its jogs stop; jobs it started go on as yours</source>
        <translation>立即结束脚本的控制权：其下一个调用将被拒绝，其点动停止；它启动的作业继续运行，改由您控制</translation>
    </message>
    <message>
        <source>%1 has had control of the bench since %2. Your motion controls ask before they act.</source>
        <translation>%1 自 %2 起控制工作台。您的运动控件在执行前会先询问。</translation>
    </message>
</context>
<context>
    <name>app::ApiPanel</name>
    <message>
        <source>Take back</source>
        <translation>收回控制权</translation>
    </message>
    <message>
        <source>Clients connected</source>
        <translation>已连接的客户端</translation>
    </message>
    <message>
        <source>Jobs started by scripts</source>
        <translation>脚本启动的作业</translation>
    </message>
    <message>
        <source>Abort job</source>
        <translation>中止作业</translation>
    </message>
    <message>
        <source>Client</source>
        <translation>客户端</translation>
    </message>
    <message>
        <source>Transport</source>
        <translation>传输方式</translation>
    </message>
    <message>
        <source>Since</source>
        <translation>起始时间</translation>
    </message>
    <message>
        <source>Calls running</source>
        <translation>运行中的调用</translation>
    </message>
    <message>
        <source>Job</source>
        <translation>作业</translation>
    </message>
    <message>
        <source>Instrument</source>
        <translation>仪器</translation>
    </message>
    <message>
        <source>Owner</source>
        <translation>所有者</translation>
    </message>
    <message>
        <source>State</source>
        <translation>状态</translation>
    </message>
    <message>
        <source>Progress</source>
        <translation>进度</translation>
    </message>
    <message>
        <source>Socket: %1 (this user only)</source>
        <translation>套接字：%1（仅限当前用户）</translation>
    </message>
    <message>
        <source>WebSocket: %1 (127.0.0.1 only, token required)</source>
        <translation>WebSocket：%1（仅限 127.0.0.1，需要令牌）</translation>
    </message>
    <message>
        <source>Control: %1, since %2</source>
        <translation>控制权：%1，自 %2 起</translation>
    </message>
    <message>
        <source>Control: the operator (you)</source>
        <translation>控制权：操作员（您）</translation>
    </message>
    <message>
        <source>End the script&apos;s control now</source>
        <translation>立即结束脚本的控制权</translation>
    </message>
    <message>
        <source>No script has control</source>
        <translation>没有脚本持有控制权</translation>
    </message>
    <message>
        <source>%1 (in control)</source>
        <translation>%1（持有控制权）</translation>
    </message>
    <message>
        <source>you (started by %1)</source>
        <translation>您（由 %1 启动）</translation>
    </message>
    <message>
        <source>Interrupt the selected job as Ctrl+C would (a recipe run raises its tip and can resume)</source>
        <translation>像 Ctrl+C 那样中断所选作业（方案运行会抬起加样针，之后可继续）</translation>
    </message>
    <message>
        <source>Select a running job to abort it</source>
        <translation>选择一个运行中的作业以中止它</translation>
    </message>
</context>
<context>
    <name>app::ApiStatusButton</name>
    <message numerus="yes">
        <source>API: %n client(s)</source>
        <translation>
            <numerusform>接口：%n 个客户端</numerusform>
        </translation>
    </message>
    <message>
        <source>Scripting API on %1</source>
        <translation>脚本接口位于 %1</translation>
    </message>
    <message>
        <source>WebSocket: %1</source>
        <translation>WebSocket：%1</translation>
    </message>
    <message>
        <source>%1 (%2), since %3</source>
        <translation>%1（%2），自 %3 起</translation>
    </message>
    <message>
        <source>Click for the API panel</source>
        <translation>点击打开接口面板</translation>
    </message>
</context>
<context>
    <name>app::ApiWiring</name>
    <message>
        <source>Scripting API not started: %1</source>
        <translation>脚本接口未启动：%1</translation>
    </message>
    <message>
        <source>Scripting API WebSocket not started: %1</source>
        <translation>脚本接口 WebSocket 未启动：%1</translation>
    </message>
    <message>
        <source>%1 has had control of the bench since %2.

Take control back? The script&apos;s next call is refused and its jogs stop; a job it started goes on as yours. Then do again what you meant to do.</source>
        <translation>%1 自 %2 起控制工作台。

收回控制权？脚本的下一个调用将被拒绝，其点动停止；它启动的作业继续运行，改由您控制。然后请重新执行您刚才想做的操作。</translation>
    </message>
    <message>
        <source>a recipe on the Plates screen</source>
        <translation>孔板界面上的加样方案</translation>
    </message>
    <message>
        <source>a scan on the Scan screen</source>
        <translation>扫描界面上的扫描</translation>
    </message>
    <message>
        <source>a pattern on the Patterns screen</source>
        <translation>图形界面上的图形</translation>
    </message>
    <message>
        <source>a test on the Tuning screen</source>
        <translation>整定界面上的测试</translation>
    </message>
    <message>
        <source>a test on the Calibration screen</source>
        <translation>校准界面上的测试</translation>
    </message>
</context>
<context>
    <name>app::HelpMenu</name>
    <message>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <source>&amp;About BenchPilot…</source>
        <translation>关于 BenchPilot(&amp;A)…</translation>
    </message>
</context>
<context>
    <name>app::InstrumentSession</name>
    <message>
        <source>stage</source>
        <translation>载物台</translation>
    </message>
    <message>
        <source>analyzer</source>
        <translation>分析仪</translation>
    </message>
    <message>
        <source>The machine profile does not load: %1</source>
        <translation>机器配置文件无法加载：%1</translation>
    </message>
    <message>
        <source>The machine profile %1 is for the %2, not the %3.</source>
        <translation>机器配置文件 %1 适用于%2，而不是%3。</translation>
    </message>
    <message>
        <source>detecting the protocol on %1…</source>
        <translation>正在检测 %1 上的通信协议…</translation>
    </message>
    <message>
        <source>%1 is a %2, not the %3: connect it in the %2&apos;s bar.</source>
        <translation>%1 是%2，不是%3：请在%2的连接栏中连接它。</translation>
    </message>
</context>
<context>
    <name>app::LongMoveQuestion</name>
    <message>
        <source>Confirm move</source>
        <translation>确认移动</translation>
    </message>
    <message>
        <source>Don&apos;t ask again this session</source>
        <translation>本次运行中不再询问</translation>
    </message>
    <message>
        <source>Long moves go ahead without this question until BenchPilot is closed. Aborting, disconnecting during a run and homing with liquid still ask.</source>
        <translation>关闭 BenchPilot 之前，长距离移动不再询问而直接执行。中止、运行中断开连接以及柱塞中有液体时回零仍会询问。</translation>
    </message>
</context>
<context>
    <name>app::MainWindow</name>
    <message>
        <source>BenchPilot</source>
        <translation>BenchPilot</translation>
    </message>
    <message>
        <source>Analyzer</source>
        <translation>分析仪</translation>
    </message>
    <message>
        <source>Stage</source>
        <translation>载物台</translation>
    </message>
    <message>
        <source>Reset E-stop</source>
        <translation>急停复位</translation>
    </message>
    <message>
        <source>Clear the E-stop latch on both instruments (axes stay where they are)</source>
        <translation>解除两台仪器的急停锁定（各轴保持原位）</translation>
    </message>
    <message>
        <source>E-STOP
(Esc)</source>
        <translation>急停
(Esc)</translation>
    </message>
    <message>
        <source>Stop all motion on both instruments at once (Esc, from any screen)</source>
        <translation>立即停止两台仪器的所有运动（在任何界面按 Esc）</translation>
    </message>
    <message>
        <source>Jog</source>
        <translation>点动</translation>
    </message>
    <message>
        <source>Plots</source>
        <translation>曲线</translation>
    </message>
    <message>
        <source>Profiles</source>
        <translation>速度曲线</translation>
    </message>
    <message>
        <source>Apply gains</source>
        <translation>应用增益</translation>
    </message>
    <message>
        <source>Tuning</source>
        <translation>整定</translation>
    </message>
    <message>
        <source>Joystick</source>
        <translation>摇杆</translation>
    </message>
    <message>
        <source>Patterns</source>
        <translation>图形</translation>
    </message>
    <message>
        <source>Plates</source>
        <translation>孔板</translation>
    </message>
    <message>
        <source>Scan</source>
        <translation>扫描</translation>
    </message>
    <message>
        <source>Event log</source>
        <translation>事件日志</translation>
    </message>
    <message>
        <source>Confirm move</source>
        <translation>确认移动</translation>
    </message>
    <message>
        <source>%1: link lost. Motion on the instrument stops by itself; reconnect when the cable is back.</source>
        <translation>%1：连接中断。仪器上的运动会自行停止；线缆恢复后请重新连接。</translation>
    </message>
    <message>
        <source> · %1 bad frames, %2 bytes skipped</source>
        <translation> · %1 个错误帧，跳过 %2 字节</translation>
    </message>
    <message>
        <source> · %1 retries, %2 timeouts</source>
        <translation> · %1 次重发，%2 次超时</translation>
    </message>
    <message>
        <source> · %1 samples lost</source>
        <translation> · 丢失 %1 个采样</translation>
    </message>
    <message>
        <source>E-STOP: all motion halted. Check the machine, then press Reset E-stop.</source>
        <translation>急停：所有运动已停止。请检查设备，然后按“急停复位”。</translation>
    </message>
    <message>
        <source>E-stop cleared. Re-home the axes if anything was moved by hand.</source>
        <translation>急停已解除。若有部件被手动移动过，请重新回零。</translation>
    </message>
    <message>
        <source>&amp;Settings</source>
        <translation>设置(&amp;S)</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>语言(&amp;L)</translation>
    </message>
    <message>
        <source>System default</source>
        <translation>跟随系统</translation>
    </message>
    <message>
        <source>settings</source>
        <translation>设置</translation>
    </message>
    <message>
        <source>the last scan plan did not load: %1</source>
        <translation>上次的扫描计划未能载入：%1</translation>
    </message>
    <message>
        <source>Calibration</source>
        <translation>校准</translation>
    </message>
    <message>
        <source>A script has control</source>
        <translation>脚本正在控制</translation>
    </message>
    <message>
        <source>Take back</source>
        <translation>收回控制权</translation>
    </message>
    <message>
        <source>Scripting API</source>
        <translation>脚本接口</translation>
    </message>
    <message>
        <source>API</source>
        <translation>API</translation>
    </message>
    <message>
        <source>server</source>
        <translation>服务器</translation>
    </message>
    <message>
        <source>link error</source>
        <translation>链路错误</translation>
    </message>
    <message>
        <source>Machine profile</source>
        <translation>机器配置</translation>
    </message>
    <message>
        <source>Machine profiles (*.machine.json);;All files (*)</source>
        <translation>机器配置文件 (*.machine.json);;所有文件 (*)</translation>
    </message>
    <message>
        <source>device</source>
        <translation>设备</translation>
    </message>
    <message>
        <source>%1: the controller no longer trusts its position (an alarm, an E-stop or a reset while it was moving). Home it, or Unlock on the Jog screen to take the position it believes.</source>
        <translation>%1：控制器已不再确信自身位置（运动中发生报警、急停或复位）。请回零，或在点动界面点击“解锁”以采用其认定的位置。</translation>
    </message>
    <message>
        <source>E-STOP: all motion halted. A GRBL controller that was moving has lost its position: home it (or unlock it on your word) before absolute moves. Check the machine, then press Reset E-stop.</source>
        <translation>急停：所有运动已停止。运动中的 GRBL 控制器已丢失位置：绝对移动前请先回零（或在确认后解锁）。检查设备后按“急停复位”。</translation>
    </message>
    <message>
        <source>a plate run</source>
        <translation>孔板运行</translation>
    </message>
    <message>
        <source>a scan</source>
        <translation>扫描</translation>
    </message>
    <message>
        <source>a tuning test</source>
        <translation>整定测试</translation>
    </message>
    <message>
        <source>a pattern</source>
        <translation>图形运动</translation>
    </message>
    <message>
        <source>%1 is running %2. Disconnect anyway? The instrument stops the job when the link goes quiet; it can be resumed after you connect again.</source>
        <translation>%1 正在进行%2。仍要断开连接吗？链路静默后仪器会停止该任务；重新连接后可以继续。</translation>
    </message>
    <message>
        <source>, </source>
        <translation>、</translation>
    </message>
    <message>
        <source>%1 is running %2</source>
        <translation>%1 正在进行%2</translation>
    </message>
    <message>
        <source>the recipe has changes that are not saved</source>
        <translation>加样方案有未保存的修改</translation>
    </message>
    <message>
        <source>Quit BenchPilot? %1.</source>
        <translation>退出 BenchPilot？%1。</translation>
    </message>
    <message>
        <source>; </source>
        <translation>；</translation>
    </message>
    <message>
        <source>%1: E-STOP latched — press Reset E-stop to clear</source>
        <translation>%1：急停已锁定 — 按“急停复位”解除</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
</context>
<context>
    <name>app::api</name>
    <message>
        <source>expected an array of numbers, got %1</source>
        <translation>应为数字数组，收到 %1</translation>
    </message>
    <message>
        <source>expected an array of numbers, found %1 in it</source>
        <translation>应为数字数组，但其中含有 %1</translation>
    </message>
    <message>
        <source>analyzer or stage; may be left out when only one is connected</source>
        <translation>analyzer 或 stage；只连接了一台仪器时可省略</translation>
    </message>
    <message>
        <source>longest wait for motion to finish, s (default: 120)</source>
        <translation>等待运动结束的最长时间，s（默认：120）</translation>
    </message>
    <message>
        <source>the lease from control.acquire (needed only when setting)</source>
        <translation>control.acquire 返回的控制权令牌（仅在设置时需要）</translation>
    </message>
    <message>
        <source>the lease from control.acquire</source>
        <translation>control.acquire 返回的控制权令牌</translation>
    </message>
    <message>
        <source>unknown parameter (this method takes none)</source>
        <translation>未知参数（此方法不接受参数）</translation>
    </message>
    <message>
        <source>unknown parameter (parameters: %1)</source>
        <translation>未知参数（参数有：%1）</translation>
    </message>
    <message>
        <source>required</source>
        <translation>必需</translation>
    </message>
    <message>
        <source>given without %1, which comes before it</source>
        <translation>给出了该参数，却缺少排在它前面的 %1</translation>
    </message>
    <message>
        <source>expected true or false, got %1</source>
        <translation>应为 true 或 false，收到 %1</translation>
    </message>
    <message>
        <source>expected a number, got %1</source>
        <translation>应为数字，收到 %1</translation>
    </message>
    <message>
        <source>expected a whole number, got %1</source>
        <translation>应为整数，收到 %1</translation>
    </message>
    <message>
        <source>expected one axis letter such as &quot;X&quot;, got %1</source>
        <translation>应为一个轴字母，如 &quot;X&quot;，收到 %1</translation>
    </message>
    <message>
        <source>expected axis letters such as &quot;XY&quot; or [&quot;X&quot;, &quot;Y&quot;]</source>
        <translation>应为轴字母，如 &quot;XY&quot; 或 [&quot;X&quot;, &quot;Y&quot;]</translation>
    </message>
    <message>
        <source>expected axis letters such as &quot;XY&quot; or [&quot;X&quot;, &quot;Y&quot;], got %1</source>
        <translation>应为轴字母，如 &quot;XY&quot; 或 [&quot;X&quot;, &quot;Y&quot;]，收到 %1</translation>
    </message>
    <message>
        <source>expected an object of axis letters, such as %1, got %2</source>
        <translation>应为以轴字母为键的对象，如 %1，收到 %2</translation>
    </message>
    <message>
        <source>not an axis letter</source>
        <translation>不是轴字母</translation>
    </message>
    <message>
        <source>expected [min, max], got %1</source>
        <translation>应为 [min, max]，收到 %1</translation>
    </message>
    <message>
        <source>expected a string, a number or an array of either</source>
        <translation>应为字符串、数字，或由二者之一组成的数组</translation>
    </message>
    <message>
        <source>expected a string, got %1</source>
        <translation>应为字符串，收到 %1</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not one of %2</source>
        <translation>&apos;%1&apos; 不在 %2 之中</translation>
    </message>
    <message>
        <source>a request is a JSON object</source>
        <translation>请求必须是一个 JSON 对象</translation>
    </message>
    <message>
        <source>parse error at byte %1: %2</source>
        <translation>第 %1 字节处解析错误：%2</translation>
    </message>
    <message>
        <source>batches are not supported: send one request per line</source>
        <translation>不支持批量请求：每行发送一个请求</translation>
    </message>
    <message>
        <source>id: must be a number or a string</source>
        <translation>id：必须是数字或字符串</translation>
    </message>
    <message>
        <source>jsonrpc: must be &quot;2.0&quot;</source>
        <translation>jsonrpc：必须为 &quot;2.0&quot;</translation>
    </message>
    <message>
        <source>method: must be a non-empty string</source>
        <translation>method：必须是非空字符串</translation>
    </message>
    <message>
        <source>params: give them by name (an object), not by position</source>
        <translation>params：请按名称给出（对象），不要按位置给出</translation>
    </message>
    <message>
        <source>params: must be an object</source>
        <translation>params：必须是对象</translation>
    </message>
    <message>
        <source>this document</source>
        <translation>本文档</translation>
    </message>
    <message>
        <source>say who is calling (shown in the GUI) and where relative paths start</source>
        <translation>说明调用者是谁（显示在图形界面中）以及相对路径的起点</translation>
    </message>
    <message>
        <source>a name for the GUI and the event log</source>
        <translation>在图形界面和事件日志中显示的名称</translation>
    </message>
    <message>
        <source>the client&apos;s working directory: relative paths in calls start here</source>
        <translation>客户端的工作目录：调用中的相对路径以此为起点</translation>
    </message>
    <message>
        <source>take the control lease (one holder at a time)</source>
        <translation>获取控制权（同一时间只有一个持有者）</translation>
    </message>
    <message>
        <source>Returns {&quot;lease&quot;: TOKEN}. Send control.heartbeat with it at least every %1 ms (100 ms is a good pace); the operator can take control back at any time.</source>
        <translation>返回 {&quot;lease&quot;: TOKEN}。请用它至少每 %1 ms 发送一次 control.heartbeat（每 100 ms 一次为宜）；操作员可随时收回控制权。</translation>
    </message>
    <message>
        <source>give the control lease back</source>
        <translation>交还控制权</translation>
    </message>
    <message>
        <source>keep the control lease (send as a notification, no id, every 100 ms)</source>
        <translation>保持控制权（以通知形式发送，不带 id，每 100 ms 一次）</translation>
    </message>
    <message>
        <source>who holds control, since when</source>
        <translation>谁持有控制权，从何时起</translation>
    </message>
    <message>
        <source>live data: positions, state, jobs, log, telemetry</source>
        <translation>实时数据：位置、状态、作业、日志、遥测</translation>
    </message>
    <message>
        <source>topic → options: {&quot;positions&quot;: {&quot;instrument&quot;: &quot;stage&quot;, &quot;max_hz&quot;: 50}, &quot;state&quot;: {}, &quot;jobs&quot;: {}, &quot;log&quot;: {}, &quot;telemetry&quot;: {&quot;instrument&quot;: &quot;stage&quot;, &quot;channels&quot;: [&quot;X.measured&quot;], &quot;rate_hz&quot;: 1000}}</source>
        <translation>主题 → 选项：{&quot;positions&quot;: {&quot;instrument&quot;: &quot;stage&quot;, &quot;max_hz&quot;: 50}, &quot;state&quot;: {}, &quot;jobs&quot;: {}, &quot;log&quot;: {}, &quot;telemetry&quot;: {&quot;instrument&quot;: &quot;stage&quot;, &quot;channels&quot;: [&quot;X.measured&quot;], &quot;rate_hz&quot;: 1000}}</translation>
    </message>
    <message>
        <source>end a subscription</source>
        <translation>结束订阅</translation>
    </message>
    <message>
        <source>the number subscribe answered</source>
        <translation>subscribe 返回的编号</translation>
    </message>
    <message>
        <source>interrupt a running call of this client, as Ctrl+C interrupts the CLI</source>
        <translation>中断本客户端正在运行的调用，如同 Ctrl+C 中断命令行工具</translation>
    </message>
    <message>
        <source>the id of the call</source>
        <translation>该调用的 id</translation>
    </message>
    <message>
        <source>run benchpilot-cli&apos;s words as benchpilot-cli --attach does: output as cli.output, then the exit code</source>
        <translation>像 benchpilot-cli --attach 那样执行 benchpilot-cli 的参数：输出以 cli.output 发送，最后给出退出码</translation>
    </message>
    <message>
        <source>the words after benchpilot-cli</source>
        <translation>benchpilot-cli 之后的参数</translation>
    </message>
    <message>
        <source>where relative paths start</source>
        <translation>相对路径的起点</translation>
    </message>
    <message>
        <source>JSON-RPC 2.0, one object per line; see docs/api.md</source>
        <translation>JSON-RPC 2.0，每行一个对象；参见 docs/api.md</translation>
    </message>
    <message>
        <source>analyzer or stage; left out, every connected instrument (never refused for not saying which)</source>
        <translation>analyzer 或 stage；省略时为每台已连接的仪器（绝不因未指明而被拒绝）</translation>
    </message>
</context>
<context>
    <name>app::api::ApiClient</name>
    <message>
        <source>pid %1</source>
        <translation>进程号 %1</translation>
    </message>
    <message>
        <source>%1 (pid %2)</source>
        <translation>%1（进程号 %2）</translation>
    </message>
    <message>
        <source>client %1</source>
        <translation>客户端 %1</translation>
    </message>
    <message>
        <source>connection closed</source>
        <translation>连接已关闭</translation>
    </message>
    <message>
        <source>it stopped reading (more than %1 MiB of answers waiting)</source>
        <translation>它已停止读取（超过 %1 MiB 的应答在等待）</translation>
    </message>
    <message>
        <source>it flooded the server (more than %1 requests waiting)</source>
        <translation>它发来的请求过多（超过 %1 个请求在等待）</translation>
    </message>
</context>
<context>
    <name>app::api::ApiServer</name>
    <message>
        <source>cannot make the folder %1 for the API socket</source>
        <translation>无法为接口套接字创建文件夹 %1</translation>
    </message>
    <message>
        <source>the folder %1 for the API socket belongs to another user</source>
        <translation>接口套接字所在的文件夹 %1 属于其他用户</translation>
    </message>
    <message>
        <source>another BenchPilot is already listening at %1</source>
        <translation>另一个 BenchPilot 已在 %1 监听</translation>
    </message>
    <message>
        <source>cannot listen at %1: %2</source>
        <translation>无法在 %1 监听：%2</translation>
    </message>
    <message>
        <source>API listening at %1</source>
        <translation>接口正在 %1 监听</translation>
    </message>
    <message>
        <source>API WebSocket listening at %1</source>
        <translation>接口 WebSocket 正在 %1 监听</translation>
    </message>
    <message>
        <source>too many clients (at most %1)</source>
        <translation>客户端过多（最多 %1 个）</translation>
    </message>
    <message>
        <source>line longer than %1 bytes: skipped to its end</source>
        <translation>行长超过 %1 字节：已跳过该行其余部分</translation>
    </message>
    <message>
        <source>connection closed</source>
        <translation>连接已关闭</translation>
    </message>
    <message>
        <source>disconnected: %1</source>
        <translation>已断开：%1</translation>
    </message>
    <message>
        <source>unknown method &apos;%1&apos; (rpc.discover lists them)</source>
        <translation>未知方法 &apos;%1&apos;（rpc.discover 可列出全部方法）</translation>
    </message>
    <message>
        <source>%1 calls are already running for this client; wait for one to end</source>
        <translation>该客户端已有 %1 个调用在运行；请等待其中一个结束</translation>
    </message>
    <message>
        <source>the GUI&apos;s %1 is not connected (%2)</source>
        <translation>图形界面中的 %1 未连接（%2）</translation>
    </message>
    <message>
        <source>the GUI has no instrument &apos;%1&apos;</source>
        <translation>图形界面中没有仪器 &apos;%1&apos;</translation>
    </message>
    <message>
        <source>no instrument is connected in the GUI</source>
        <translation>图形界面中没有已连接的仪器</translation>
    </message>
    <message>
        <source>not in control: the operator runs %1</source>
        <translation>未持有控制权：操作员正在运行%1</translation>
    </message>
    <message>
        <source>not in control: pass the lease from control.acquire as &quot;lease&quot;</source>
        <translation>未持有控制权：请将 control.acquire 返回的控制权令牌作为 &quot;lease&quot; 传入</translation>
    </message>
    <message>
        <source>not in control: that lease is not the one this client holds</source>
        <translation>未持有控制权：该控制权令牌不是本客户端所持有的</translation>
    </message>
    <message>
        <source>not in control: %1 has had control since %2</source>
        <translation>未持有控制权：%1 自 %2 起持有控制权</translation>
    </message>
    <message>
        <source>not in control: call control.acquire first (the operator can take control back at any time)</source>
        <translation>未持有控制权：请先调用 control.acquire（操作员可随时收回控制权）</translation>
    </message>
    <message>
        <source>%1 that %2 started goes on, and is now yours (%3)</source>
        <translation>%2 启动的 %1 继续运行，现在由您控制（%3）</translation>
    </message>
    <message>
        <source>%1: unknown parameter (this method takes none)</source>
        <translation>%1：未知参数（此方法不接受参数）</translation>
    </message>
    <message>
        <source>%1: unknown parameter (parameters: %2)</source>
        <translation>%1：未知参数（参数有：%2）</translation>
    </message>
    <message>
        <source>%1: expected a string</source>
        <translation>%1：应为字符串</translation>
    </message>
    <message>
        <source>the operator runs %1: control stays with the GUI until it ends</source>
        <translation>操作员正在运行%1：在其结束前控制权留在图形界面</translation>
    </message>
    <message>
        <source>%1 has had control since %2</source>
        <translation>%1 自 %2 起持有控制权</translation>
    </message>
    <message>
        <source>took control</source>
        <translation>取得了控制权</translation>
    </message>
    <message>
        <source>not in control: this client does not hold that lease (taken back, expired or released)</source>
        <translation>未持有控制权：本客户端并未持有该控制权令牌（已被收回、已过期或已交还）</translation>
    </message>
    <message>
        <source>subscription: expected the number subscribe answered</source>
        <translation>subscription：应为 subscribe 返回的编号</translation>
    </message>
    <message>
        <source>argv: expected an array of strings (benchpilot-cli&apos;s words)</source>
        <translation>argv：应为字符串数组（benchpilot-cli 的参数）</translation>
    </message>
    <message>
        <source>%1 calls are already running for this client</source>
        <translation>该客户端已有 %1 个调用在运行</translation>
    </message>
    <message>
        <source>the analyzer and the stage are both connected: say which with --instrument analyzer|stage</source>
        <translation>分析仪和载物台都已连接：请用 --instrument analyzer|stage 指明是哪一台</translation>
    </message>
</context>
<context>
    <name>app::api::CommandCall</name>
    <message>
        <source>%1: done</source>
        <translation>%1：完成</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>失败</translation>
    </message>
    <message>
        <source>failed with exit code %1</source>
        <translation>失败，退出码 %1</translation>
    </message>
    <message>
        <source>%1 on the %2</source>
        <translation>%2 上的 %1</translation>
    </message>
    <message>
        <source>inside the GUI its own connections are used: --port does not apply (name the instrument with --instrument analyzer|stage)</source>
        <translation>在图形界面内使用其自身的连接：--port 不适用（请用 --instrument analyzer|stage 指定仪器）</translation>
    </message>
    <message>
        <source>%1 on every connected instrument (%2)</source>
        <translation>每台已连接仪器（%2）上的 %1</translation>
    </message>
</context>
<context>
    <name>app::api::Subscriptions</name>
    <message>
        <source>unknown parameter (parameters: topics)</source>
        <translation>未知参数（参数有：topics）</translation>
    </message>
    <message>
        <source>expected an object of topics, e.g. {&quot;positions&quot;: {&quot;instrument&quot;: &quot;stage&quot;, &quot;max_hz&quot;: 50}}</source>
        <translation>应为以主题为键的对象，例如 {&quot;positions&quot;: {&quot;instrument&quot;: &quot;stage&quot;, &quot;max_hz&quot;: 50}}</translation>
    </message>
    <message>
        <source>unknown topic (topics: positions, state, jobs, log, telemetry)</source>
        <translation>未知主题（主题有：positions, state, jobs, log, telemetry）</translation>
    </message>
    <message>
        <source>expected an object of options (max_hz, instrument, …), {} for the defaults</source>
        <translation>应为选项对象（max_hz, instrument, …），{} 表示使用默认值</translation>
    </message>
    <message>
        <source>unknown option (options: %1)</source>
        <translation>未知选项（选项有：%1）</translation>
    </message>
    <message>
        <source>expected a number above 0 and at most %1</source>
        <translation>应为大于 0 且不大于 %1 的数</translation>
    </message>
    <message>
        <source>expected one of %1</source>
        <translation>应为 %1 之一</translation>
    </message>
    <message>
        <source>telemetry is not available here (no telemetry hub)</source>
        <translation>此处无法使用遥测（没有遥测中心）</translation>
    </message>
    <message>
        <source>expected an array such as [&quot;X.measured&quot;, &quot;X.following_error&quot;]</source>
        <translation>应为数组，例如 [&quot;X.measured&quot;, &quot;X.following_error&quot;]</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a channel of the %2 (AXIS.measured, AXIS.commanded, AXIS.velocity, AXIS.following_error, AXIS.controller_output, AXIS.switches, contour_error)</source>
        <translation>&apos;%1&apos; 不是 %2 的通道（AXIS.measured, AXIS.commanded, AXIS.velocity, AXIS.following_error, AXIS.controller_output, AXIS.switches, contour_error）</translation>
    </message>
    <message>
        <source>expected samples per second, 1 or more</source>
        <translation>应为每秒采样数，不小于 1</translation>
    </message>
</context>
<context>
    <name>app::api::WebSocketEndpoint</name>
    <message>
        <source>the token file %1 can be read by others (chmod 600 it)</source>
        <translation>令牌文件 %1 可被其他用户读取（请对其执行 chmod 600）</translation>
    </message>
    <message>
        <source>cannot read the token file %1: %2</source>
        <translation>无法读取令牌文件 %1：%2</translation>
    </message>
    <message>
        <source>the token in %1 is too short (at least 16 characters)</source>
        <translation>%1 中的令牌太短（至少 16 个字符）</translation>
    </message>
    <message>
        <source>cannot write the token file %1: %2</source>
        <translation>无法写入令牌文件 %1：%2</translation>
    </message>
    <message>
        <source>cannot listen on 127.0.0.1:%1: %2</source>
        <translation>无法在 127.0.0.1:%1 上监听：%2</translation>
    </message>
    <message>
        <source>origin not allowed</source>
        <translation>不允许该来源</translation>
    </message>
    <message>
        <source>a token is required (?token=… from the token file)</source>
        <translation>需要令牌（?token=…，取自令牌文件）</translation>
    </message>
    <message>
        <source>this BenchPilot was built without Qt WebSockets (install qt6-websockets-dev: ./scripts/setup)</source>
        <translation>此 BenchPilot 构建时未包含 Qt WebSockets（请安装 qt6-websockets-dev：./scripts/setup）</translation>
    </message>
</context>
<context>
    <name>app::cli</name>
    <message>
        <source>show this help</source>
        <translation>显示本帮助</translation>
    </message>
    <message>
        <source>show the program&apos;s version</source>
        <translation>显示程序版本</translation>
    </message>
    <message>
        <source> (default: %1)</source>
        <translation>（默认：%1）</translation>
    </message>
    <message>
        <source>--sim needs &apos;analyzer&apos; or &apos;stage&apos; (got &apos;%1&apos;)</source>
        <translation>--sim 需要 &apos;analyzer&apos; 或 &apos;stage&apos;（收到 &apos;%1&apos;）</translation>
    </message>
    <message>
        <source>--port needs a path</source>
        <translation>--port 需要一个路径</translation>
    </message>
    <message>
        <source>--baud needs a rate of at least 1200 (got &apos;%1&apos;)</source>
        <translation>--baud 需要不低于 1200 的速率（收到 &apos;%1&apos;）</translation>
    </message>
    <message>
        <source>--timeout needs a positive number of seconds (got &apos;%1&apos;)</source>
        <translation>--timeout 需要正的秒数（收到 &apos;%1&apos;）</translation>
    </message>
    <message>
        <source>unknown option %1 (options: %2)</source>
        <translation>未知选项 %1（可用选项：%2）</translation>
    </message>
    <message>
        <source>a serial port, or the pty of benchpilot-sim</source>
        <translation>串口，或 benchpilot-sim 的 pty</translation>
    </message>
    <message>
        <source>link speed (default: 115200)</source>
        <translation>链路速率（默认：115200）</translation>
    </message>
    <message>
        <source>print JSON instead of text</source>
        <translation>输出 JSON 而非文本</translation>
    </message>
    <message>
        <source>longest wait for motion to finish, s (default: 120)</source>
        <translation>等待运动结束的最长时间，s（默认：120）</translation>
    </message>
    <message>
        <source>language of the text for people: en (default), zh_CN, or system (follows LANG); --json never changes</source>
        <translation>面向用户的文本语言：en（默认）、zh_CN 或 system（跟随 LANG）；--json 输出始终不变</translation>
    </message>
    <message>
        <source>
Global options (before or after the command):
</source>
        <translation>
全局选项（可放在命令之前或之后）：
</translation>
    </message>
    <message>
        <source>
&apos;benchpilot-cli COMMAND --help&apos; shows a command&apos;s options. Options take their value as
&apos;--opt value&apos; or &apos;--opt=value&apos;.
Exit codes: 0 ok, 1 usage, 2 refused or motion failed, 3 link trouble.
Bash completion: source &lt;(benchpilot-cli completion bash)
</source>
        <translation>
&apos;benchpilot-cli 命令 --help&apos; 显示该命令的选项。选项的值可写作
&apos;--opt value&apos; 或 &apos;--opt=value&apos;。
退出码：0 成功，1 用法错误，2 被拒绝或运动失败，3 连接故障。
Bash 补全：source &lt;(benchpilot-cli completion bash)
</translation>
    </message>
    <message>
        <source>usage: benchpilot-cli %1 SUBCOMMAND [OPTIONS] [ARGUMENTS]

%2

Subcommands:
</source>
        <translation>用法：benchpilot-cli %1 子命令 [选项] [参数]

%2

子命令：
</translation>
    </message>
    <message>
        <source>
&apos;benchpilot-cli %1 SUBCOMMAND --help&apos; shows a subcommand&apos;s options.
</source>
        <translation>
&apos;benchpilot-cli %1 子命令 --help&apos; 显示该子命令的选项。
</translation>
    </message>
    <message>
        <source>usage: benchpilot-cli %1%2%3

%4
</source>
        <translation>用法：benchpilot-cli %1%2%3

%4
</translation>
    </message>
    <message>
        <source> [OPTIONS]</source>
        <translation> [选项]</translation>
    </message>
    <message>
        <source>
Options:
</source>
        <translation>
选项：
</translation>
    </message>
    <message>
        <source>--lang needs en, zh_CN or system (got &apos;%1&apos;)</source>
        <translation>--lang 需要 en、zh_CN 或 system（收到 &apos;%1&apos;）</translation>
    </message>
    <message>
        <source>try &apos;benchpilot-cli --help&apos;
</source>
        <translation>请尝试 &apos;benchpilot-cli --help&apos;
</translation>
    </message>
    <message>
        <source>no command given</source>
        <translation>未给出命令</translation>
    </message>
    <message>
        <source>unknown command &apos;%1&apos; (commands: %2)</source>
        <translation>未知命令 &apos;%1&apos;（可用命令：%2）</translation>
    </message>
    <message>
        <source>which one? (%1)</source>
        <translation>是哪一个？（%1）</translation>
    </message>
    <message>
        <source>unknown subcommand &apos;%1&apos; (%2)</source>
        <translation>未知子命令 &apos;%1&apos;（%2）</translation>
    </message>
    <message>
        <source>try &apos;benchpilot-cli %1 --help&apos;
</source>
        <translation>请尝试 &apos;benchpilot-cli %1 --help&apos;
</translation>
    </message>
    <message>
        <source>give either --sim or --port, not both</source>
        <translation>--sim 和 --port 只能给出其一，不能同时给出</translation>
    </message>
    <message>
        <source>cannot connect to %1: %2</source>
        <translation>无法连接到 %1：%2</translation>
    </message>
    <message>
        <source>no answer within %1 s</source>
        <translation>%1 s 内无应答</translation>
    </message>
    <message>
        <source>axis &apos;%1&apos; does not exist on the %2 (axes: %3)</source>
        <translation>%2上不存在轴 &apos;%1&apos;（可用轴：%3）</translation>
    </message>
    <message>
        <source>%1: no answer</source>
        <translation>%1：无应答</translation>
    </message>
    <message>
        <source>%1: link lost while waiting</source>
        <translation>%1：等待期间连接中断</translation>
    </message>
    <message>
        <source>%1: still moving after %2 s; sent stop</source>
        <translation>%1：%2 s 后仍在运动；已发送停止命令</translation>
    </message>
    <message>
        <source>only &apos;bash&apos; is supported: source &lt;(benchpilot-cli completion bash)</source>
        <translation>只支持 &apos;bash&apos;：source &lt;(benchpilot-cli completion bash)</translation>
    </message>
    <message>
        <source>print a bash completion script</source>
        <translation>输出 bash 补全脚本</translation>
    </message>
    <message>
        <source>Use: source &lt;(benchpilot-cli completion bash)</source>
        <translation>用法：source &lt;(benchpilot-cli completion bash)</translation>
    </message>
    <message>
        <source>takes no arguments (got &apos;%1&apos;)</source>
        <translation>不接受参数（收到 &apos;%1&apos;）</translation>
    </message>
    <message>
        <source>planner limits: not reported (estimates assume the reference machine&apos;s)</source>
        <translation>规划器限值：设备未报告（估算按参考机器的限值）</translation>
    </message>
    <message>
        <source>home</source>
        <translation>回零</translation>
    </message>
    <message>
        <source>--speed needs a positive number</source>
        <translation>--speed 需要一个正数</translation>
    </message>
    <message>
        <source>give at least one AXIS=VALUE</source>
        <translation>请至少给出一个 AXIS=VALUE</translation>
    </message>
    <message>
        <source>expected AXIS=VALUE, got &apos;%1&apos;</source>
        <translation>应为 AXIS=VALUE，收到 &apos;%1&apos;</translation>
    </message>
    <message>
        <source>axis &apos;%1&apos; does not exist on the %2</source>
        <translation>%2上不存在轴 &apos;%1&apos;</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a number for axis %2</source>
        <translation>&apos;%1&apos; 不是轴 %2 的有效数值</translation>
    </message>
    <message>
        <source>move</source>
        <translation>移动</translation>
    </message>
    <message>
        <source>expected AXIS VELOCITY SECONDS</source>
        <translation>应为 AXIS VELOCITY SECONDS</translation>
    </message>
    <message>
        <source>velocity &apos;%1&apos; is not a number</source>
        <translation>速度 &apos;%1&apos; 不是数字</translation>
    </message>
    <message>
        <source>seconds must be in (0, 600]</source>
        <translation>秒数必须在 (0, 600] 范围内</translation>
    </message>
    <message>
        <source>velocity must be within ±%1 %2/s</source>
        <translation>速度必须在 ±%1 %2/s 以内</translation>
    </message>
    <message>
        <source>jog</source>
        <translation>点动</translation>
    </message>
    <message>
        <source>stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>estop</source>
        <translation>急停</translation>
    </message>
    <message>
        <source>reset</source>
        <translation>复位</translation>
    </message>
    <message>
        <source>name the axes to zero, e.g. &apos;zero XY&apos;</source>
        <translation>请指定要设零点的轴，例如 &apos;zero XY&apos;</translation>
    </message>
    <message>
        <source>zero</source>
        <translation>设零点</translation>
    </message>
    <message>
        <source>expected AXIS=MIN:MAX, got &apos;%1&apos;</source>
        <translation>应为 AXIS=MIN:MAX，收到 &apos;%1&apos;</translation>
    </message>
    <message>
        <source>limits</source>
        <translation>软限位</translation>
    </message>
    <message>
        <source>targets are distances from where the axes are</source>
        <translation>目标是相对各轴当前位置的距离</translation>
    </message>
    <message>
        <source>path speed in the unit of the first axis named, per second</source>
        <translation>路径速度，单位为所列第一个轴的单位每秒</translation>
    </message>
    <message>
        <source>device identity, axes, travel, resolution</source>
        <translation>设备标识、轴、行程、分辨率</translation>
    </message>
    <message>
        <source>positions (commanded and measured), homed, moving, switches</source>
        <translation>位置（指令值和测量值）、是否已回零、是否在运动、开关状态</translation>
    </message>
    <message>
        <source>home the axes (all when none given), wait until done</source>
        <translation>轴回零（未指定时全部回零），并等待完成</translation>
    </message>
    <message>
        <source>The analyzer lifts Z first. AXES are letters, e.g. &apos;XY&apos;.</source>
        <translation>分析仪先抬起 Z 轴。轴用字母表示，例如 &apos;XY&apos;。</translation>
    </message>
    <message>
        <source>move and wait until done (mm, µL for P)</source>
        <translation>移动并等待完成（单位 mm，P 轴为 µL）</translation>
    </message>
    <message>
        <source>Absolute moves need homed axes; targets beyond the soft limits are refused by the device.</source>
        <translation>绝对移动要求轴已回零；超出软限位的目标会被设备拒绝。</translation>
    </message>
    <message>
        <source>velocity jog for SECONDS, then stop and wait until still</source>
        <translation>以给定速度点动指定秒数，然后停止并等待停稳</translation>
    </message>
    <message>
        <source>The jog is refreshed while it runs; if this program dies the device stops the axis by itself.</source>
        <translation>点动运行期间会不断刷新；若本程序意外退出，设备会自行停止该轴。</translation>
    </message>
    <message>
        <source>decelerate all axes to rest</source>
        <translation>所有轴减速至停止</translation>
    </message>
    <message>
        <source>halt at once and latch the E-stop</source>
        <translation>立即停止并锁定急停</translation>
    </message>
    <message>
        <source>clear the E-stop latch</source>
        <translation>解除急停锁定</translation>
    </message>
    <message>
        <source>make the current position zero</source>
        <translation>将当前位置设为零点</translation>
    </message>
    <message>
        <source>show or set soft limits</source>
        <translation>显示或设置软限位</translation>
    </message>
    <message>
        <source>--%1 is required</source>
        <translation>--%1 为必填项</translation>
    </message>
    <message>
        <source>--%1 &apos;%2&apos; is not a number</source>
        <translation>--%1 &apos;%2&apos; 不是数字</translation>
    </message>
    <message>
        <source>--%1 &apos;%2&apos;: &apos;%3&apos; is not a number</source>
        <translation>--%1 &apos;%2&apos;：&apos;%3&apos; 不是数字</translation>
    </message>
    <message>
        <source>--%1 &apos;%2&apos; needs %3 comma-separated numbers</source>
        <translation>--%1 &apos;%2&apos; 需要 %3 个以逗号分隔的数</translation>
    </message>
    <message>
        <source>plan a motion profile and print s, v, a, j samples (JSON)</source>
        <translation>规划速度曲线并输出 s、v、a、j 采样（JSON）</translation>
    </message>
    <message>
        <source>See docs/motion.md for the profiles and the seeds they come from.</source>
        <translation>速度曲线及其来源文献见 docs/motion.md。</translation>
    </message>
    <message>
        <source>point-by-point line or arc, or sine/cosine by chords (JSON)</source>
        <translation>逐点比较法直线或圆弧插补，或以弦线逼近正弦/余弦（JSON）</translation>
    </message>
    <message>
        <source>line: --to X,Y [--from X,Y]; arc: --start, --center, --to, --dir cw|ccw; sine|cosine: --amplitude, --wavelength, --length, --tolerance. All need --step (mm).</source>
        <translation>直线：--to X,Y [--from X,Y]；圆弧：--start、--center、--to、--dir cw|ccw；正弦|余弦：--amplitude、--wavelength、--length、--tolerance。都需要 --step（mm）。</translation>
    </message>
    <message>
        <source>seed 001 step-period table of a profile or of seed 001&apos;s own move (JSON)</source>
        <translation>文献 001 的步进周期表：针对某条速度曲线或文献 001 自身的移动（JSON）</translation>
    </message>
    <message>
        <source>Whole interrupt periods plus a remainder per step, with the zero-match correction.</source>
        <translation>每步为整数个中断周期加余数，并含零匹配修正。</translation>
    </message>
    <message>
        <source>plan seed 004 blocks per joint and pack them into CAN frames (JSON)</source>
        <translation>按关节规划文献 004 的块，并打包成 CAN 帧（JSON）</translation>
    </message>
    <message>
        <source>--joint S:V2:t0_ms,S:V2:t0_ms,… once per joint.</source>
        <translation>--joint S:V2:t0_ms,S:V2:t0_ms,…，每个关节给出一次。</translation>
    </message>
    <message>
        <source>--dir must be cw or ccw (got &apos;%1&apos;)</source>
        <translation>--dir 必须为 cw 或 ccw（收到 &apos;%1&apos;）</translation>
    </message>
    <message>
        <source>give --shape (line, rectangle, circle, arc, sine, cosine, spiral, raster) or --file</source>
        <translation>请给出 --shape（line, rectangle, circle, arc, sine, cosine, spiral, raster）或 --file</translation>
    </message>
    <message>
        <source>--shape &apos;%1&apos; is not one of line, rectangle, circle, arc, sine, cosine, spiral, raster</source>
        <translation>--shape &apos;%1&apos; 不是 line, rectangle, circle, arc, sine, cosine, spiral, raster 之一</translation>
    </message>
    <message>
        <source>--along must be x or y (got &apos;%1&apos;)</source>
        <translation>--along 必须为 x 或 y（收到 &apos;%1&apos;）</translation>
    </message>
    <message>
        <source>takes options only (got &apos;%1&apos;)</source>
        <translation>只接受选项（收到 &apos;%1&apos;）</translation>
    </message>
    <message>
        <source>%1: %2 segments, %3 mm, about %4 s on the %5 simulator&apos;s limits
</source>
        <translation>%1：%2 段，%3 mm，按 %5 仿真器的限值约需 %4 s
</translation>
    </message>
    <message>
        <source>homing did not finish</source>
        <translation>回零未完成</translation>
    </message>
    <message>
        <source>(every --sim command starts a fresh simulator: add --home-first)</source>
        <translation>（每条 --sim 命令都会启动一个新的仿真器：请加上 --home-first）</translation>
    </message>
    <message>
        <source>the pattern did not finish within --timeout %1 s: aborted</source>
        <translation>图形未在 --timeout %1 s 内完成：已中止</translation>
    </message>
    <message>
        <source>the pattern did not complete</source>
        <translation>图形未完成</translation>
    </message>
    <message>
        <source>plan a pattern (line, rectangle, circle, arc, sine, cosine, spiral, raster) or run it and measure the contour error</source>
        <translation>规划图形（line, rectangle, circle, arc, sine, cosine, spiral, raster）或运行它并测量轮廓误差</translation>
    </message>
    <message>
        <source>Shape options not given keep the pattern&apos;s defaults (docs/patterns.md). --file reads a *.pattern.json; shape options then change it.</source>
        <translation>未给出的形状选项沿用图形的默认值（docs/patterns.md）。--file 读取 *.pattern.json，形状选项再对其修改。</translation>
    </message>
    <message>
        <source>print the segments, length and estimated time without moving</source>
        <translation>输出各段、总长和估计时间，不运动</translation>
    </message>
    <message>
        <source>Timed on the limits of the simulator --sim names (the stage when none).</source>
        <translation>按 --sim 所指仿真器的限值计时（未指定时为载物台）。</translation>
    </message>
    <message>
        <source>run the pattern on the instrument; print max and RMS contour error (µm) and duration</source>
        <translation>在仪器上运行图形；输出最大和均方根轮廓误差（µm）及用时</translation>
    </message>
    <message>
        <source>Moves to the pattern&apos;s start (XY, then Z on the analyzer), streams the segments into the device&apos;s path queue and judges the measured XY from telemetry against the path. Exit 2 if it is refused or does not complete.</source>
        <translation>移动到图形起点（先 XY，分析仪上再移 Z），将各段流式送入设备的路径队列，并根据遥测中实测的 XY 相对路径进行评判。被拒绝或未完成时退出码为 2。</translation>
    </message>
    <message>
        <source>%1: valid: %2 ops, about %3 s</source>
        <translation>%1：有效：%2 个操作，约 %3 s</translation>
    </message>
    <message>
        <source>%1: %2 errors</source>
        <translation>%1：%2 个错误</translation>
    </message>
    <message>
        <source>%1 ops · %2 µL dispensed, %3 µL aspirated · plunger %4 → %5 µL · total %6 s</source>
        <translation>%1 个操作 · 排液 %2 µL，吸液 %3 µL · 柱塞 %4 → %5 µL · 总计 %6 s</translation>
    </message>
    <message>
        <source>validate, plan and run dispensing recipes on the analyzer (docs/recipes.md)</source>
        <translation>在分析仪上检查、规划并运行加样方案（docs/recipes.md）</translation>
    </message>
    <message>
        <source>check a recipe: every problem with its line, column and field</source>
        <translation>检查加样方案：列出每个问题及其行、列和字段</translation>
    </message>
    <message>
        <source>Exit 0 when the recipe can run (warnings allowed), 1 with every error otherwise. Nothing moves.</source>
        <translation>方案可运行时（允许有警告）退出码为 0，否则列出所有错误并返回 1。不会有任何运动。</translation>
    </message>
    <message>
        <source>the dry run: each op and move with well, x, y, z, volume, and the total time</source>
        <translation>空运行：列出每个操作和移动的孔、x、y、z、体积以及总时间</translation>
    </message>
    <message>
        <source>Planned from the machine at home (0, 0, 0) with an empty syringe. Nothing moves.</source>
        <translation>按机器位于零位 (0, 0, 0)、注射器为空进行规划。不会有任何运动。</translation>
    </message>
    <message>
        <source>the run log to write (a new file; default RECIPE-DATE.run.jsonl here)</source>
        <translation>要写入的运行日志（新文件；默认为当前目录下的 RECIPE-DATE.run.jsonl）</translation>
    </message>
    <message>
        <source>continue the run this log records; wells done are not done again</source>
        <translation>继续该日志所记录的运行；已完成的孔不会重做</translation>
    </message>
    <message>
        <source>a well interrupted after its plunger moved: skip (count it done) or redo it; asked for, never guessed</source>
        <translation>柱塞已移动后被中断的孔：跳过（计为已完成）或重做；必须明确指定，绝不猜测</translation>
    </message>
    <message>
        <source>home the analyzer first</source>
        <translation>先让分析仪回零</translation>
    </message>
    <message>
        <source>run a recipe, logging every well so it can be resumed</source>
        <translation>运行加样方案，记录每个孔，以便之后继续</translation>
    </message>
    <message>
        <source>Prints a line per well (one JSON object with --json). Ctrl+C aborts: the tip rises and the log can resume. Exit 2 when the device refuses or the run stops, 3 when the link is lost.</source>
        <translation>每个孔输出一行（使用 --json 时为一个 JSON 对象）。Ctrl+C 中止：加样针抬起，之后可按日志继续。设备拒绝或运行停止时退出码为 2，连接中断时为 3。</translation>
    </message>
    <message>
        <source>give --log for a new run or --resume for one to continue, not both</source>
        <translation>新运行请给出 --log，继续运行请给出 --resume，两者不能同时给出</translation>
    </message>
    <message>
        <source>--interrupted must be skip or redo (got &apos;%1&apos;)</source>
        <translation>--interrupted 必须为 skip 或 redo（收到 &apos;%1&apos;）</translation>
    </message>
    <message>
        <source>%1 does not validate: nothing moved</source>
        <translation>%1 未通过检查：没有任何运动</translation>
    </message>
    <message>
        <source>no run log %1 to resume</source>
        <translation>没有可继续的运行日志 %1</translation>
    </message>
    <message>
        <source>%1 exists: a run log is never overwritten (continue it with --resume, or name another with --log)</source>
        <translation>%1 已存在：运行日志绝不会被覆盖（用 --resume 继续它，或用 --log 指定其他文件名）</translation>
    </message>
    <message>
        <source>%1 was interrupted after its plunger move was sent: %2</source>
        <translation>%1 在其柱塞移动命令发出后被中断：%2</translation>
    </message>
    <message>
        <source>interrupted: aborting (the tip rises, the log can resume)</source>
        <translation>已中断：正在中止（加样针抬起，之后可按日志继续）</translation>
    </message>
    <message>
        <source>not resumed: say --interrupted=skip (count the well as done) or --interrupted=redo (do it again)</source>
        <translation>未继续：请指定 --interrupted=skip（将该孔计为已完成）或 --interrupted=redo（重做该孔）</translation>
    </message>
    <message>
        <source>log: %1</source>
        <translation>日志：%1</translation>
    </message>
    <message>
        <source>the deck definition (default: the built-in analyzer deck)</source>
        <translation>台面定义（默认：内置的分析仪台面）</translation>
    </message>
    <message>
        <source>slot calibration (default: the one the GUI keeps, %1); &quot;none&quot; for the nominal slots</source>
        <translation>板位校准（默认：图形界面保存的校准，%1）；&quot;none&quot; 表示使用名义板位</translation>
    </message>
    <message>
        <source>name one recipe file</source>
        <translation>请指定一个加样方案文件</translation>
    </message>
    <message>
        <source>--%1 &apos;%2&apos; needs 1 to %3 comma-separated numbers</source>
        <translation>--%1 &apos;%2&apos; 需要 1 到 %3 个以逗号分隔的数</translation>
    </message>
    <message>
        <source>give the region: --roi x0,y0,x1,y1, --centre x,y with --size w,h, or --polygon &apos;x,y;x,y;…&apos;</source>
        <translation>请给出区域：--roi x0,y0,x1,y1，--centre x,y 加 --size w,h，或 --polygon &apos;x,y;x,y;…&apos;</translation>
    </message>
    <message>
        <source>give one region: --roi, --centre/--size or --polygon</source>
        <translation>只能给出一种区域：--roi、--centre/--size 或 --polygon</translation>
    </message>
    <message>
        <source>--polygon: corner &apos;%1&apos; is not x,y in mm</source>
        <translation>--polygon：角点 &apos;%1&apos; 不是以 mm 为单位的 x,y</translation>
    </message>
    <message>
        <source>give the camera field: --fov w,h in mm, or --sensor W,H px with --sensor-um and --mag</source>
        <translation>请给出相机视场：--fov w,h（mm），或 --sensor W,H（像素）加 --sensor-um 和 --mag</translation>
    </message>
    <message>
        <source>--sensor &apos;%1&apos; must be two whole pixel counts</source>
        <translation>--sensor &apos;%1&apos; 必须是两个整数像素数</translation>
    </message>
    <message>
        <source>--order &apos;%1&apos; is not one of snake-rows, rows, snake-cols, cols</source>
        <translation>--order &apos;%1&apos; 不是 snake-rows, rows, snake-cols, cols 之一</translation>
    </message>
    <message>
        <source>--start &apos;%1&apos; is not one of top-left, top-right, bottom-left, bottom-right</source>
        <translation>--start &apos;%1&apos; 不是 top-left, top-right, bottom-left, bottom-right 之一</translation>
    </message>
    <message>
        <source>--format &apos;%1&apos; is not one of json, summary, tileconfig, mmpos, csv</source>
        <translation>--format &apos;%1&apos; 不是 json, summary, tileconfig, mmpos, csv 之一</translation>
    </message>
    <message>
        <source>takes at most one plan file (got &apos;%1&apos;)</source>
        <translation>最多只接受一个计划文件（收到 &apos;%1&apos;）</translation>
    </message>
    <message>
        <source>give a plan file or the plan&apos;s options, not both (--%1)</source>
        <translation>计划文件和计划选项只能给出其一（--%1）</translation>
    </message>
    <message>
        <source>--pixel-um: the plan&apos;s camera gives the pixel size (sensor pixel / magnification)</source>
        <translation>--pixel-um：像素尺寸由计划中的相机给出（传感器像素 / 放大倍数）</translation>
    </message>
    <message>
        <source>--format tileconfig gives pixels: add --pixel-um (one pixel at the sample, µm)</source>
        <translation>--format tileconfig 以像素为单位：请加上 --pixel-um（样品处一个像素的尺寸，µm）</translation>
    </message>
    <message>
        <source>needs one plan file: scan run PLAN.json [--out DIR]</source>
        <translation>需要一个计划文件：scan run PLAN.json [--out DIR]</translation>
    </message>
    <message>
        <source>scans run on the microscope stage; this is the %1 (use --sim stage or --port)</source>
        <translation>扫描只能在显微镜载物台上运行；当前仪器是%1（请用 --sim stage 或 --port）</translation>
    </message>
    <message>
        <source> (--restart starts over)</source>
        <translation>（--restart 重新开始）</translation>
    </message>
    <message>
        <source>Every tile of this scan is already taken in %1; exports written again. --restart takes them anew.
</source>
        <translation>此扫描的所有图块已在 %1 中采集完毕；导出文件已重新写入。--restart 会重新采集。
</translation>
    </message>
    <message>
        <source> (--home homes the stage first)</source>
        <translation>（--home 会先让载物台回零）</translation>
    </message>
    <message>
        <source>this scan takes about %1 min on the stage; add --yes to run it</source>
        <translation>此扫描在载物台上约需 %1 min；加上 --yes 才会运行</translation>
    </message>
    <message>
        <source>Continuing at tile %1 of %2 (the run log in %3 has the first %4).
</source>
        <translation>从第 %1 个图块继续（共 %2 个；%3 中的运行日志已记录前 %4 个）。
</translation>
    </message>
    <message>
        <source>tile %1/%2 %3 at %4, %5 mm (%6 s to settle)
</source>
        <translation>图块 %1/%2 %3 位于 %4, %5 mm（稳定用时 %6 s）
</translation>
    </message>
    <message>
        <source> Run the same command again to continue.</source>
        <translation> 再次运行同一命令即可继续。</translation>
    </message>
    <message>
        <source>%1 tiles taken; wrote %2
</source>
        <translation>已采集 %1 个图块；已写入 %2
</translation>
    </message>
    <message>
        <source>plan a stitching scan and print it (plan file, summary, Fiji, Micro-Manager or CSV)</source>
        <translation>规划拼接扫描并输出（计划文件、摘要、Fiji、Micro-Manager 或 CSV）</translation>
    </message>
    <message>
        <source>[PLAN.json]</source>
        <translation>[PLAN.json]</translation>
    </message>
    <message>
        <source>The tile grid steps by exactly field × (1 − overlap), centred on the region: n = max(1, ceil((W − F)/(F(1 − o))) + 1) per axis. Checked against the standard 100 × 100 mm stage. With PLAN.json, prints that plan in --format.</source>
        <translation>图块网格的步距恰为视场 × (1 − 重叠率)，并以区域为中心：每个轴 n = max(1, ceil((W − F)/(F(1 − o))) + 1)。按标准 100 × 100 mm 载物台检查。给出 PLAN.json 时，按 --format 输出该计划。</translation>
    </message>
    <message>
        <source>run a scan plan on the stage, continue a stopped run, write the exports</source>
        <translation>在载物台上运行扫描计划，继续已停止的运行，并写出导出文件</translation>
    </message>
    <message>
        <source>PLAN.json</source>
        <translation>PLAN.json</translation>
    </message>
    <message>
        <source>stitching scans on the stage: plan, run</source>
        <translation>载物台上的拼接扫描：规划、运行</translation>
    </message>
    <message>
        <source>See docs/scan.md for the grid rule, the plan file and the exports.</source>
        <translation>网格规则、计划文件和导出文件见 docs/scan.md。</translation>
    </message>
    <message>
        <source>Kp %1, Ki %2 /s, Kd %3 s</source>
        <translation>Kp %1，Ki %2 /s，Kd %3 s</translation>
    </message>
    <message>
        <source>gains are three numbers Kp,Ki,Kd (got &apos;%1&apos;)</source>
        <translation>增益是三个数 Kp,Ki,Kd（收到 &apos;%1&apos;）</translation>
    </message>
    <message>
        <source>%1 &apos;%2&apos; is not a number</source>
        <translation>%1 &apos;%2&apos; 不是数字</translation>
    </message>
    <message>
        <source>homing the axis first</source>
        <translation>先让该轴回零</translation>
    </message>
    <message>
        <source>the axis did not come to rest</source>
        <translation>该轴未能停稳</translation>
    </message>
    <message>
        <source>give --sim stage or --port PATH</source>
        <translation>请给出 --sim stage 或 --port PATH</translation>
    </message>
    <message>
        <source>give either --plant or an instrument (--sim/--port with --axis), not both</source>
        <translation>--plant 与仪器（--sim/--port 加 --axis）只能给出其一，不能同时给出</translation>
    </message>
    <message>
        <source>--plant: %1</source>
        <translation>--plant：%1</translation>
    </message>
    <message>
        <source>give --axis X (a closed-loop axis) or --plant SPEC</source>
        <translation>请给出 --axis X（闭环轴）或 --plant SPEC</translation>
    </message>
    <message>
        <source>could not start</source>
        <translation>无法开始</translation>
    </message>
    <message>
        <source>no result within %1 s (--timeout): aborted; the axis is stopped</source>
        <translation>%1 s 内没有结果（--timeout）：已中止；该轴已停止</translation>
    </message>
    <message>
        <source>the link was lost; the device ended the test and holds the axis under its gains</source>
        <translation>连接中断；设备已结束测试，并以其增益保持该轴</translation>
    </message>
    <message>
        <source>--method must be zn (ultimate gain) or relay</source>
        <translation>--method 必须为 zn（临界增益）或 relay（继电）</translation>
    </message>
    <message>
        <source>--verify: no rule &apos;%1&apos;</source>
        <translation>--verify：没有规则 &apos;%1&apos;</translation>
    </message>
    <message>
        <source>relay</source>
        <translation>继电法</translation>
    </message>
    <message>
        <source>ultimate gain</source>
        <translation>临界增益法</translation>
    </message>
    <message>
        <source> runs</source>
        <translation> 次试验</translation>
    </message>
    <message>
        <source>  classic describing function: Ku = %1, Tu = %2 s%3
</source>
        <translation>  经典描述函数法：Ku = %1，Tu = %2 s%3
</translation>
    </message>
    <message>
        <source> (refined above)</source>
        <translation>（上方为细化后的结果）</translation>
    </message>
    <message>
        <source>  rule                       Kp          Ki [1/s]    Kd [s]      | per period T = %1 s: kp, ki, kd
</source>
        <translation>  规则                       Kp          Ki [1/s]    Kd [s]      | 每周期 T = %1 s：kp, ki, kd
</translation>
    </message>
    <message>
        <source>  verified with %1: overshoot %2 %, %3
</source>
        <translation>  用 %1 验证：超调量 %2 %，%3
</translation>
    </message>
    <message>
        <source>--size must be a non-zero number (mm on an instrument, signed for the direction)</source>
        <translation>--size 必须是非零数（在仪器上以 mm 为单位，正负号表示方向）</translation>
    </message>
    <message>
        <source>--gains: %1</source>
        <translation>--gains：%1</translation>
    </message>
    <message>
        <source>a model plant has no gains of its own: give --gains Kp,Ki,Kd</source>
        <translation>模型对象没有自身的增益：请给出 --gains Kp,Ki,Kd</translation>
    </message>
    <message>
        <source>: step %1 %2 with </source>
        <translation>：阶跃 %1 %2，增益 </translation>
    </message>
    <message>
        <source>  rise 10–90 %: %1 s, overshoot %2 %, settling (2 %): %3 s
</source>
        <translation>  上升时间（10–90 %）：%1 s，超调量 %2 %，调节时间（2 %）：%3 s
</translation>
    </message>
    <message>
        <source>  steady-state error %1 %4, IAE %2 %4·s, ISE %3 %4²·s, peak output %5 %4
</source>
        <translation>  稳态误差 %1 %4，IAE %2 %4·s，ISE %3 %4²·s，输出峰值 %5 %4
</translation>
    </message>
    <message>
        <source>  never inside seed 002&apos;s ±5 µm band
</source>
        <translation>  始终未进入文献 002 的 ±5 µm 带内
</translation>
    </message>
    <message>
        <source>  inside seed 002&apos;s ±5 µm band from %1 s
</source>
        <translation>  自 %1 s 起进入文献 002 的 ±5 µm 带内
</translation>
    </message>
    <message>
        <source>expected AXIS=Kp,Ki,Kd with a closed-loop axis, got &apos;%1&apos;</source>
        <translation>应为 AXIS=Kp,Ki,Kd，且须为闭环轴，收到 &apos;%1&apos;</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>set gains</source>
        <translation>设置增益</translation>
    </message>
    <message>
        <source>  (per period T = %1 s: kp %2, ki %3, kd %4)</source>
        <translation>  （每周期 T = %1 s：kp %2，ki %3，kd %4）</translation>
    </message>
    <message>
        <source>; power-up set differs</source>
        <translation>；上电增益组与此不同</translation>
    </message>
    <message>
        <source>a model plant instead of an instrument: fopdt:K=..,tau=..,L=.. or lag:K=..,tau=..,n=..</source>
        <translation>用模型对象代替仪器：fopdt:K=..,tau=..,L=.. 或 lag:K=..,tau=..,n=..</translation>
    </message>
    <message>
        <source>the instrument&apos;s closed-loop axis</source>
        <translation>仪器的闭环轴</translation>
    </message>
    <message>
        <source>home the axis and move it to mid-travel first (always done on the in-process simulator)</source>
        <translation>先让该轴回零并移到行程中点（在进程内仿真器上总会执行）</translation>
    </message>
    <message>
        <source>envelope: the furthest from the start (mm; plant units)</source>
        <translation>安全包络：离起点的最大距离（mm；或对象单位）</translation>
    </message>
    <message>
        <source>envelope: the largest |setpoint − position|</source>
        <translation>安全包络：|设定值 − 位置| 的最大值</translation>
    </message>
    <message>
        <source>envelope: the longest a test may run, s</source>
        <translation>安全包络：测试的最长运行时间，s</translation>
    </message>
    <message>
        <source>gains are eq. 2&apos;s per-period kp,ki,kd, not Kp, Ki [1/s], Kd [s]</source>
        <translation>增益为式 2 的每周期 kp,ki,kd，而不是 Kp、Ki [1/s]、Kd [s]</translation>
    </message>
    <message>
        <source>find Ku and Tu (Ziegler–Nichols) and print the tuning rules</source>
        <translation>求 Ku 和 Tu（Ziegler–Nichols）并输出整定规则</translation>
    </message>
    <message>
        <source>--method zn raises Kp trial by trial (P only) until the oscillation neither grows nor decays; --method relay runs Åström and Hägglund&apos;s relay, then refines to the measured phase crossover. Trials run inside 60 % of the envelope. Ki and Kd are printed in continuous form (1/s, s).</source>
        <translation>--method zn 逐次试验提高 Kp（仅比例控制），直到振荡既不发散也不衰减；--method relay 运行 Åström 和 Hägglund 的继电测试，然后细化到实测的相位穿越点。试验在安全包络的 60 % 以内进行。Ki 和 Kd 以连续形式输出（1/s、s）。</translation>
    </message>
    <message>
        <source>zn (ultimate gain) or relay</source>
        <translation>zn（临界增益）或 relay（继电）</translation>
    </message>
    <message>
        <source>relay: d, of the controller output (mm; plant units)</source>
        <translation>relay：继电幅值 d，即控制器输出的幅值（mm；或对象单位）</translation>
    </message>
    <message>
        <source>relay: ε (mm; plant units)</source>
        <translation>relay：滞环 ε（mm；或对象单位）</translation>
    </message>
    <message>
        <source>zn: each trial&apos;s setpoint step (mm; plant units)</source>
        <translation>zn：每次试验的设定值阶跃（mm；或对象单位）</translation>
    </message>
    <message>
        <source>relay: only the classic describing-function estimate</source>
        <translation>relay：仅给出经典描述函数法的估计值</translation>
    </message>
    <message>
        <source>run a step test with this rule&apos;s gains afterwards (zn-pid, tl-pi, …)</source>
        <translation>之后用该规则的增益运行阶跃测试（zn-pid, tl-pi, …）</translation>
    </message>
    <message>
        <source>write the results to a .tuning.json file</source>
        <translation>将结果写入 .tuning.json 文件</translation>
    </message>
    <message>
        <source>a step on one axis under given (or the axis&apos; own) gains; print its metrics</source>
        <translation>在给定增益（或该轴自身增益）下对单轴施加阶跃；输出其指标</translation>
    </message>
    <message>
        <source>--size in mm (signed: the direction). --gains Kp,Ki,Kd are tried for this test only: the axis&apos; own gains stay.</source>
        <translation>--size 以 mm 为单位（正负号表示方向）。--gains Kp,Ki,Kd 只在本次测试中试用：轴自身的增益保持不变。</translation>
    </message>
    <message>
        <source>step size, mm (plant units); negative steps down</source>
        <translation>阶跃大小，mm（或对象单位）；负值表示反向阶跃</translation>
    </message>
    <message>
        <source>Kp,Ki,Kd for this test (Ki in 1/s, Kd in s)</source>
        <translation>本次测试的 Kp,Ki,Kd（Ki 单位 1/s，Kd 单位 s）</translation>
    </message>
    <message>
        <source>show or set the PID gains of the closed-loop axes</source>
        <translation>显示或设置闭环轴的 PID 增益</translation>
    </message>
    <message>
        <source>Kp, Ki in 1/s, Kd in s (per period with --per-period). The device refuses NaN, negative and absurd values with its reason and keeps the gains it had.</source>
        <translation>Kp、Ki（1/s）、Kd（s）（使用 --per-period 时为每周期值）。设备会拒绝 NaN、负值和不合理的值并说明原因，同时保留原有增益。</translation>
    </message>
    <message>
        <source>also keep them as the device&apos;s power-up gains</source>
        <translation>同时保存为设备的上电增益</translation>
    </message>
    <message>
        <source>Axis %1, %2, %3 cycles, %4 targets (ISO 230-2, µm)</source>
        <translation>%1 轴，%2，%3 个循环，%4 个目标位置（ISO 230-2，µm）</translation>
    </message>
    <message>
        <source>bidirectional</source>
        <translation>双向</translation>
    </message>
    <message>
        <source>unidirectional</source>
        <translation>单向</translation>
    </message>
    <message>
        <source>pass</source>
        <translation>合格</translation>
    </message>
    <message>
        <source>FAIL</source>
        <translation>不合格</translation>
    </message>
    <message>
        <source>--%1 must be above 0 mm</source>
        <translation>--%1 必须大于 0 mm</translation>
    </message>
    <message>
        <source>give one readings CSV</source>
        <translation>请给出一个读数 CSV 文件</translation>
    </message>
    <message>
        <source>give --sequence TARGETS.csv and the interferometer&apos;s CSV export</source>
        <translation>请给出 --sequence TARGETS.csv 和激光干涉仪导出的 CSV 文件</translation>
    </message>
    <message>
        <source>wrote %1</source>
        <translation>已写入 %1</translation>
    </message>
    <message>
        <source>%1 is not a circular test</source>
        <translation>%1 不是圆测试</translation>
    </message>
    <message>
        <source>give --radius R (mm), or --test FILE</source>
        <translation>请给出 --radius R（mm）或 --test FILE</translation>
    </message>
    <message>
        <source>--time-scale speeds up the in-process simulator: use it with --sim</source>
        <translation>--time-scale 用于加速进程内仿真器：请与 --sim 一起使用</translation>
    </message>
    <message>
        <source>Circular test, radius %1 mm</source>
        <translation>圆测试，半径 %1 mm</translation>
    </message>
    <message>
        <source>G %1: %2 µm</source>
        <translation>G %1：%2 µm</translation>
    </message>
    <message>
        <source>H: %1 µm</source>
        <translation>H：%1 µm</translation>
    </message>
    <message>
        <source>ISO 230-2 positioning tests, ISO 230-4 circular tests, their analysis</source>
        <translation>ISO 230-2 定位测试、ISO 230-4 圆测试及其分析</translation>
    </message>
    <message>
        <source>run a positioning test on an axis and evaluate it (ISO 230-2)</source>
        <translation>在某轴上运行定位测试并评定（ISO 230-2）</translation>
    </message>
    <message>
        <source>Moves through the standard linear cycle, takes a reading at every stop once the axis has settled, and writes the readings CSV, the result JSON and the PDF report into --out. A run that stopped continues from its log there.</source>
        <translation>按标准线性循环移动，在每个停止点待轴稳定后取一个读数，并将读数 CSV、结果 JSON 和 PDF 报告写入 --out。已停止的运行会依据该处的日志继续。</translation>
    </message>
    <message>
        <source>ISO 230-2 figures of a readings CSV</source>
        <translation>由读数 CSV 计算 ISO 230-2 指标</translation>
    </message>
    <message>
        <source>READINGS.csv</source>
        <translation>READINGS.csv</translation>
    </message>
    <message>
        <source>run a circular test on X and Y (ISO 230-4)</source>
        <translation>在 X 和 Y 上运行圆测试（ISO 230-4）</translation>
    </message>
    <message>
        <source>an interferometer&apos;s CSV export matched to a run&apos;s target sequence</source>
        <translation>将激光干涉仪导出的 CSV 与某次运行的目标位置序列相匹配</translation>
    </message>
    <message>
        <source>EXPORT.csv</source>
        <translation>EXPORT.csv</translation>
    </message>
    <message>
        <source>--targets &apos;%1&apos;: START:END:COUNT, such as 10:90:9, or a list such as 10,30,50</source>
        <translation>--targets &apos;%1&apos;：应为 START:END:COUNT，如 10:90:9，或列表，如 10,30,50</translation>
    </message>
    <message>
        <source>%1 is a circular test: run it with &apos;accuracy circle --test&apos;</source>
        <translation>%1 是圆测试：请用 &apos;accuracy circle --test&apos; 运行</translation>
    </message>
    <message>
        <source>give --targets START:END:COUNT (or a list), or --test FILE</source>
        <translation>请给出 --targets START:END:COUNT（或列表），或 --test FILE</translation>
    </message>
    <message>
        <source>--cycles &apos;%1&apos; must be a whole number</source>
        <translation>--cycles &apos;%1&apos; 必须是整数</translation>
    </message>
    <message>
        <source>--time-scale must be from 0 to 100</source>
        <translation>--time-scale 必须在 0 到 100 之间</translation>
    </message>
    <message>
        <source><byte value="xd"/>%1 of %2 readings, about %3 s left   </source>
        <translation><byte value="xd"/>已取得 %1/%2 个读数，约剩 %3 s   </translation>
    </message>
    <message>
        <source>Positioning accuracy of axis %1</source>
        <translation>%1 轴定位精度</translation>
    </message>
    <message>
        <source>contour error: A↑ %1 µm, R↑ %2 µm</source>
        <translation>轮廓误差：A↑ %1 µm，R↑ %2 µm</translation>
    </message>
    <message>
        <source>reading %1 of %2: %3%4, cycle %5; type the reading in mm (q aborts): </source>
        <translation>读数 %1/%2：%3%4，循环 %5；请输入读数，单位 mm（输入 q 中止）：</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a reading here; </source>
        <translation>&apos;%1&apos; 不是此处有效的读数；</translation>
    </message>
    <message>
        <source>no BenchPilot GUI is running with its API at %1. Start benchpilot (with --api-socket %1 if that is where it should listen), or leave out --attach to open the instrument directly.</source>
        <translation>没有接口位于 %1 的 BenchPilot 图形界面在运行。请启动 benchpilot（若应在该处监听，请加上 --api-socket %1），或去掉 --attach 以直接打开仪器。</translation>
    </message>
    <message>
        <source>cannot reach the BenchPilot GUI at %1: %2</source>
        <translation>无法连接到位于 %1 的 BenchPilot 图形界面：%2</translation>
    </message>
    <message>
        <source>the GUI at %1 does not take the command: %2</source>
        <translation>位于 %1 的图形界面不接受该命令：%2</translation>
    </message>
    <message>
        <source>the GUI closed the connection before the command finished</source>
        <translation>命令完成前图形界面关闭了连接</translation>
    </message>
    <message>
        <source>--instrument needs &apos;analyzer&apos; or &apos;stage&apos; (got &apos;%1&apos;)</source>
        <translation>--instrument 需要 &apos;analyzer&apos; 或 &apos;stage&apos;（收到 &apos;%1&apos;）</translation>
    </message>
    <message>
        <source>--profile needs a machine profile file</source>
        <translation>--profile 需要一个机器配置文件</translation>
    </message>
    <message>
        <source>--profile: %1</source>
        <translation>--profile：%1</translation>
    </message>
    <message>
        <source>with --port: the machine profile of a GRBL controller, a file or the name of one BenchPilot ships (stage-grbl-uno; docs/grbl.md)</source>
        <translation>与 --port 一起使用：GRBL 控制器的机器配置文件，可以是文件，也可以是 BenchPilot 自带配置的名称（stage-grbl-uno；docs/grbl.md）</translation>
    </message>
    <message>
        <source>run the command through the running BenchPilot GUI (its instruments, its control lease)</source>
        <translation>通过正在运行的 BenchPilot 图形界面执行命令（使用其仪器及其控制权）</translation>
    </message>
    <message>
        <source>usage: benchpilot-cli [GLOBAL OPTIONS] COMMAND [OPTIONS] [ARGUMENTS]

Scripts BenchPilot&apos;s instruments (the in-process simulators, benchpilot-sim&apos;s pty, or a
serial port: BenchPilot firmware, or a GRBL 1.1 / grblHAL controller) and its motion library.

Commands:
</source>
        <translation>用法：benchpilot-cli [全局选项] 命令 [选项] [参数]

以脚本方式操作 BenchPilot 的仪器（进程内仿真器、benchpilot-sim 的 pty，或
串口：BenchPilot 固件，或 GRBL 1.1 / grblHAL 控制器）及其运动库。

命令：
</translation>
    </message>
    <message>
        <source>
Global options: --sim KIND, --port PATH, --baud N, --instrument KIND, --profile FILE, --json, --timeout S (see benchpilot-cli --help).
</source>
        <translation>
全局选项：--sim KIND, --port PATH, --baud N, --instrument KIND, --profile FILE, --json, --timeout S（参见 benchpilot-cli --help）。
</translation>
    </message>
    <message>
        <source>--api-socket goes with --attach</source>
        <translation>--api-socket 须与 --attach 一起使用</translation>
    </message>
    <message>
        <source>--attach is already in effect here</source>
        <translation>此处 --attach 已经生效</translation>
    </message>
    <message>
        <source>[ALARM] the controller does not trust its position: home, or `unlock` on your word</source>
        <translation>[报警] 控制器不再确信自身位置：请回零，或在确认后执行 `unlock`</translation>
    </message>
    <message>
        <source>give one result JSON or error-curve CSV</source>
        <translation>请给出一个结果 JSON 或误差曲线 CSV</translation>
    </message>
    <message>
        <source>--order &apos;%1&apos;: auto or 1 to 5</source>
        <translation>--order &apos;%1&apos;：应为 auto 或 1 到 5</translation>
    </message>
    <message>
        <source>--kind &apos;%1&apos;: polynomial or table</source>
        <translation>--kind &apos;%1&apos;：应为 polynomial 或 table</translation>
    </message>
    <message>
        <source>--kind table needs a result JSON: a table is made from each target&apos;s means</source>
        <translation>--kind table 需要结果 JSON：补偿表由各目标位置的平均值生成</translation>
    </message>
    <message>
        <source>order  SSE (µm²)        R²         adjusted R²</source>
        <translation>阶数   SSE (µm²)        R²         调整后 R²</translation>
    </message>
    <message>
        <source>n/a</source>
        <translation>无</translation>
    </message>
    <message>
        <source>e(x) = %1 µm over %2 … %3 mm; backlash %4 µm</source>
        <translation>e(x) = %1 µm，范围 %2 … %3 mm；反向间隙 %4 µm</translation>
    </message>
    <message>
        <source>axis %1: no compensation</source>
        <translation>%1 轴：无补偿</translation>
    </message>
    <message>
        <source>polynomial of order %1 over %2 … %3 mm</source>
        <translation>%1 阶多项式，范围 %2 … %3 mm</translation>
    </message>
    <message>
        <source>table of %1 points%2</source>
        <translation>%1 点补偿表%2</translation>
    </message>
    <message>
        <source> per direction</source>
        <translation>（分方向）</translation>
    </message>
    <message>
        <source>axis %1: %2, backlash %3 µm; %4%5%6</source>
        <translation>%1 轴：%2，反向间隙 %3 µm；%4%5%6</translation>
    </message>
    <message>
        <source>enabled</source>
        <translation>已启用</translation>
    </message>
    <message>
        <source>disabled</source>
        <translation>已禁用</translation>
    </message>
    <message>
        <source> (applied once the axis is homed)</source>
        <translation>（轴回零后生效）</translation>
    </message>
    <message>
        <source>, kept for power-up</source>
        <translation>，已保存为上电设置</translation>
    </message>
    <message>
        <source>give one compensation file</source>
        <translation>请给出一个补偿文件</translation>
    </message>
    <message>
        <source>--format &apos;%1&apos;: linuxcnc or csv</source>
        <translation>--format &apos;%1&apos;：应为 linuxcnc 或 csv</translation>
    </message>
    <message>
        <source>--type &apos;%1&apos;: 0 (positions reached) or 1 (corrections)</source>
        <translation>--type &apos;%1&apos;：应为 0（到达的位置）或 1（修正量）</translation>
    </message>
    <message>
        <source>axis error compensation: fit, keep on the device, export</source>
        <translation>轴误差补偿：拟合、保存到设备、导出</translation>
    </message>
    <message>
        <source>fit error polynomials of orders 1–5 to a result or an error curve</source>
        <translation>对结果或误差曲线拟合 1–5 阶误差多项式</translation>
    </message>
    <message>
        <source>INPUT</source>
        <translation>输入</translation>
    </message>
    <message>
        <source>INPUT is a result JSON of &apos;accuracy run&apos; or &apos;accuracy analyze&apos;, or a CSV with position_mm,error_um. The order is chosen by adjusted R² unless --order names one; --out writes the compensation file.</source>
        <translation>输入为 &apos;accuracy run&apos; 或 &apos;accuracy analyze&apos; 的结果 JSON，或含 position_mm,error_um 列的 CSV。除非 --order 指定阶数，否则按调整后 R² 选择阶数；--out 写出补偿文件。</translation>
    </message>
    <message>
        <source>send a compensation file to the device (installed disabled)</source>
        <translation>将补偿文件发送到设备（安装后处于禁用状态）</translation>
    </message>
    <message>
        <source>FILE</source>
        <translation>文件</translation>
    </message>
    <message>
        <source>the device&apos;s compensation of an axis</source>
        <translation>设备上某轴的补偿</translation>
    </message>
    <message>
        <source>enable the device&apos;s compensation of an axis</source>
        <translation>启用设备上某轴的补偿</translation>
    </message>
    <message>
        <source>disable the device&apos;s compensation of an axis</source>
        <translation>禁用设备上某轴的补偿</translation>
    </message>
    <message>
        <source>a compensation as CSV or a LinuxCNC compensation file</source>
        <translation>将补偿导出为 CSV 或 LinuxCNC 补偿文件</translation>
    </message>
    <message>
        <source>[FILE]</source>
        <translation>[文件]</translation>
    </message>
    <message>
        <source>Exports FILE, or the device&apos;s compensation of --axis when no FILE is given. LinuxCNC: --type 0 writes the positions the joint reaches, --type 1 the corrections (COMP_FILE_TYPE).</source>
        <translation>导出给定的文件；未给出文件时，导出设备上 --axis 所指轴的补偿。LinuxCNC：--type 0 写出关节到达的位置，--type 1 写出修正量（COMP_FILE_TYPE）。</translation>
    </message>
    <message>
        <source>nothing to unlock: the instrument trusts its position</source>
        <translation>无需解锁：仪器确信自身位置</translation>
    </message>
    <message>
        <source>unlocking: the position the controller believes is taken as true; home the axes when you can</source>
        <translation>正在解锁：以控制器认定的位置为准；请尽快让各轴回零</translation>
    </message>
    <message>
        <source>unlock</source>
        <translation>解锁</translation>
    </message>
    <message>
        <source>the axes to home, e.g. &quot;XY&quot;; all when left out</source>
        <translation>要回零的轴，例如 &quot;XY&quot;；省略时全部回零</translation>
    </message>
    <message>
        <source>axis → target, e.g. {&quot;X&quot;: 10, &quot;Y&quot;: 5}</source>
        <translation>轴 → 目标位置，例如 {&quot;X&quot;: 10, &quot;Y&quot;: 5}</translation>
    </message>
    <message>
        <source>the axis letter</source>
        <translation>轴字母</translation>
    </message>
    <message>
        <source>axis units per second, signed</source>
        <translation>每秒的轴单位数，带正负号</translation>
    </message>
    <message>
        <source>jog this long, then stop and wait until still; without it the jog runs until device.stop, or until the lease or the connection ends</source>
        <translation>点动这么长时间，然后停止并等待停稳；省略时点动一直进行，直到 device.stop，或控制权或连接结束</translation>
    </message>
    <message>
        <source>On a GRBL controller without homing ($22=0) this takes the present position as home, on your word: absolute moves are allowed after it.</source>
        <translation>在未启用回零（$22=0）的 GRBL 控制器上，这会按您的确认将当前位置作为零位：之后允许绝对移动。</translation>
    </message>
    <message>
        <source>the axes to zero, e.g. &quot;XY&quot;</source>
        <translation>要设零点的轴，例如 &quot;XY&quot;</translation>
    </message>
    <message>
        <source>accept the position a controller believes after an alarm (GRBL&apos;s $X)</source>
        <translation>报警后采用控制器认定的位置（GRBL 的 $X）</translation>
    </message>
    <message>
        <source>After an alarm that lost the position (a reset while moving, an E-stop, a hard limit) a GRBL controller refuses motion until it is homed or unlocked. Unlocking takes its idea of the position as true: home when you can.</source>
        <translation>发生丢失位置的报警后（运动中复位、急停、硬限位），GRBL 控制器在回零或解锁前拒绝运动。解锁即以其认定的位置为准：请尽快回零。</translation>
    </message>
    <message>
        <source>axis → [min, max] to set; shows them when left out</source>
        <translation>轴 → 要设置的 [min, max]；省略时显示当前值</translation>
    </message>
    <message>
        <source>one joint&apos;s blocks &quot;S:V2:t0_ms,…&quot;; an array of such strings for several joints</source>
        <translation>一个关节的块 &quot;S:V2:t0_ms,…&quot;；多个关节时为此类字符串组成的数组</translation>
    </message>
    <message>
        <source>%1 on the %2: %3 of %4 segments in %5 s; contour error max %6 µm, RMS %7 µm (%8 samples at %9 Hz)
</source>
        <translation>%2上的 %1：%5 s 内完成 %3/%4 段；轮廓误差最大 %6 µm，均方根 %7 µm（%8 个采样点，%9 Hz）
</translation>
    </message>
    <message>
        <source>the recipe file</source>
        <translation>加样方案文件</translation>
    </message>
    <message>
        <source>a plan file to print in another format (instead of the plan&apos;s options)</source>
        <translation>要以另一种格式输出的计划文件（代替计划选项）</translation>
    </message>
    <message>
        <source>the scan plan file</source>
        <translation>扫描计划文件</translation>
    </message>
    <message>
        <source>axis → [Kp, Ki, Kd] to set; shows them when left out</source>
        <translation>轴 → 要设置的 [Kp, Ki, Kd]；省略时显示当前值</translation>
    </message>
    <message>
        <source>--time-scale speeds up benchpilot-cli&apos;s own simulator; the GUI&apos;s simulators keep their pace</source>
        <translation>--time-scale 只加速 benchpilot-cli 自己的仿真器；图形界面的仿真器保持原有速度</translation>
    </message>
    <message>
        <source>the readings CSV</source>
        <translation>读数 CSV 文件</translation>
    </message>
    <message>
        <source>the interferometer software&apos;s CSV export</source>
        <translation>干涉仪软件导出的 CSV 文件</translation>
    </message>
    <message>
        <source>a result JSON, or a CSV with position_mm,error_um</source>
        <translation>结果 JSON，或含 position_mm,error_um 列的 CSV</translation>
    </message>
    <message>
        <source>the compensation file</source>
        <translation>补偿文件</translation>
    </message>
    <message>
        <source>a compensation file; the device&apos;s when left out</source>
        <translation>补偿文件；省略时使用设备上的补偿</translation>
    </message>
    <message>
        <source>E-STOP</source>
        <translation>急停</translation>
    </message>
    <message>
        <source>cmd</source>
        <translation>指令</translation>
    </message>
    <message>
        <source>meas</source>
        <translation>实测</translation>
    </message>
    <message>
        <source>homed</source>
        <translation>已回零</translation>
    </message>
    <message>
        <source>NOT HOMED</source>
        <translation>未回零</translation>
    </message>
    <message>
        <source>moving</source>
        <translation>运动中</translation>
    </message>
    <message>
        <source>home-switch</source>
        <translation>零位开关</translation>
    </message>
    <message>
        <source>limit-switch</source>
        <translation>限位开关</translation>
    </message>
    <message>
        <source>%1: link lost while waiting: %2</source>
        <translation>%1：等待期间连接中断：%2</translation>
    </message>
    <message>
        <source>finished: %1 of %2 operations in %3</source>
        <translation>已完成：%2 项操作中的 %1 项，用时 %3</translation>
    </message>
    <message>
        <source>stopped after %1 of %2 operations; continue with: benchpilot-cli recipe run %3 --resume %4</source>
        <translation>在 %2 项操作中完成 %1 项后停止；继续请用：benchpilot-cli recipe run %3 --resume %4</translation>
    </message>
    <message>
        <source>the in-process simulator: analyzer or stage (default: analyzer); with --attach, the older spelling of --instrument</source>
        <translation>进程内仿真器：analyzer 或 stage（默认：analyzer）；与 --attach 一起使用时，是 --instrument 的旧写法</translation>
    </message>
    <message>
        <source>with --port: which instrument it is, analyzer or stage (default: what the device says; a GRBL controller: the profile&apos;s, else the analyzer); with --attach: which of the GUI&apos;s instruments, whatever it is connected to (may be left out when only one is; stop and estop without it halt every one)</source>
        <translation>与 --port 一起使用：它是哪台仪器，analyzer 或 stage（默认：以设备所报为准；GRBL 控制器：以配置文件为准，否则为分析仪）；与 --attach 一起使用：图形界面中的哪台仪器，不论它连接的是什么（只有一台已连接时可省略；不带它的 stop 和 estop 会停下每一台）</translation>
    </message>
    <message>
        <source>with --attach: the GUI&apos;s API socket (default: %1; $XDG_RUNTIME_DIR/benchpilot/api.sock, or /tmp/benchpilot-UID/api.sock without XDG_RUNTIME_DIR)</source>
        <translation>与 --attach 一起使用：图形界面的接口套接字（默认：%1；即 $XDG_RUNTIME_DIR/benchpilot/api.sock，未设置 XDG_RUNTIME_DIR 时为 /tmp/benchpilot-UID/api.sock）</translation>
    </message>
    <message>
        <source>--instrument %1 and --sim %2 name different instruments</source>
        <translation>--instrument %1 与 --sim %2 指的是不同的仪器</translation>
    </message>
    <message>
        <source>--instrument goes with --port, or with --attach to name the GUI&apos;s instrument (--sim names its simulator itself)</source>
        <translation>--instrument 须与 --port 一起使用，或与 --attach 一起使用以指明图形界面的仪器（--sim 自身已指明其仿真器）</translation>
    </message>
    <message>
        <source>--profile goes with --port</source>
        <translation>--profile 须与 --port 一起使用</translation>
    </message>
    <message>
        <source>--new-run keeps every run; --restart sets one aside: give one of them</source>
        <translation>--new-run 保留每次运行，--restart 把一次运行放到一边：只能给其中一个</translation>
    </message>
    <message>
        <source>%1 holds a finished run of this test: this run goes into %2, beside it.</source>
        <translation>%1 中已有此测试完成的一次运行：这次运行写入它旁边的 %2。</translation>
    </message>
    <message>
        <source>%1 holds a finished run of this test: its results follow, nothing was moved. To run the test again beside it (after compensation), add --new-run: it goes into %2 and both are kept.</source>
        <translation>%1 中已有此测试完成的一次运行：下面是它的结果，机器没有移动。要在它旁边再运行一次此测试（例如补偿之后），请加上 --new-run：它写入 %2，两次运行都会保留。</translation>
    </message>
    <message>
        <source>  verdict: settled
</source>
        <translation>  判定：已稳定
</translation>
    </message>
    <message>
        <source>  verdict: did not settle within 2 % of the step
</source>
        <translation>  判定：未稳定在阶跃的 2 % 以内
</translation>
    </message>
    <message>
        <source>  verdict: unstable
</source>
        <translation>  判定：不稳定
</translation>
    </message>
    <message>
        <source>  verdict: never comes to rest: a limit cycle of ±%1 %2 every %3 s
</source>
        <translation>  判定：始终未静止：仍有 ±%1 %2、周期 %3 s 的极限环
</translation>
    </message>
    <message>
        <source>time-optimal bound %1 s: the plan takes %2 times the bound</source>
        <translation>时间最优下限 %1 s：计划用时是下限的 %2 倍</translation>
    </message>
    <message>
        <source>order %1: %2 s, bound %3 s</source>
        <translation>顺序 %1：%2 s，下限 %3 s</translation>
    </message>
    <message>
        <source>order %1: a step cannot take it</source>
        <translation>顺序 %1：有步骤不能采用</translation>
    </message>
    <message>
        <source>also plan every well order (as-written, column-major, snake-rows, snake-columns, shortest): time and bound of each</source>
        <translation>同时按每种孔顺序（按书写、逐列、行蛇形、列蛇形、最短路径）规划：给出各自的用时和下限</translation>
    </message>
    <message>
        <source>--source manual reads what a person types at benchpilot-cli; in the GUI use the Calibration screen</source>
        <translation>--source manual 读取操作员在 benchpilot-cli 中输入的读数；在图形界面中请使用“校准”界面</translation>
    </message>
    <message>
        <source>--gauge-timeout must be from 0 to 60 s</source>
        <translation>--gauge-timeout 必须在 0 到 60 s 之间</translation>
    </message>
    <message>
        <source>--source gauge:sim is benchpilot-cli&apos;s own simulator&apos;s gauge: inside the GUI give the gauge&apos;s port, or use the Calibration screen&apos;s simulated gauge</source>
        <translation>--source gauge:sim 是 benchpilot-cli 自带仿真器的测头：在图形界面中请给出测头的端口，或使用“校准”界面的模拟测头</translation>
    </message>
    <message>
        <source>--source gauge:sim reads the in-process simulator&apos;s gauge: use it with --sim</source>
        <translation>--source gauge:sim 读取进程内仿真器的测头：请与 --sim 一起使用</translation>
    </message>
    <message>
        <source>simulated gauge</source>
        <translation>模拟测头</translation>
    </message>
    <message>
        <source>the simulated camera on the in-process simulator&apos;s stage (--sim stage)</source>
        <translation>进程内模拟器载物台上的模拟相机（--sim stage）</translation>
    </message>
    <message>
        <source>the simulated camera benchpilot-sim serves on a socket (--camera-socket)</source>
        <translation>benchpilot-sim 在套接字上提供的模拟相机（--camera-socket）</translation>
    </message>
    <message>
        <source>your capture program, run for each image with {file} {tile} {x_mm} {y_mm}</source>
        <translation>您自己的采集程序，每张图像运行一次，填入 {file} {tile} {x_mm} {y_mm}</translation>
    </message>
    <message>
        <source>the next complete new image a camera&apos;s own software saves in DIR</source>
        <translation>相机自带软件在 DIR 中保存的下一张完整新图像</translation>
    </message>
    <message>
        <source> (not in this build yet)</source>
        <translation>（本版本尚未提供）</translation>
    </message>
    <message>
        <source>Simulated specimens (--specimen): %1
</source>
        <translation>模拟样品（--specimen）：%1
</translation>
    </message>
    <message>
        <source>needs --out FILE.tif</source>
        <translation>需要 --out FILE.tif</translation>
    </message>
    <message>
        <source>--out &apos;%1&apos;: the image is a TIFF, give a name ending in .tif</source>
        <translation>--out &apos;%1&apos;：图像是 TIFF 文件，请给出以 .tif 结尾的文件名</translation>
    </message>
    <message>
        <source>--exposure-ms must be above 0 and at most 60000</source>
        <translation>--exposure-ms 必须大于 0 且不超过 60000</translation>
    </message>
    <message>
        <source>the camera %1 gave no image within %2 s</source>
        <translation>相机 %1 在 %2 秒内没有给出图像</translation>
    </message>
    <message>
        <source>wrote %1: %2 × %3 px, %4-bit, %5 ms</source>
        <translation>已写入 %1：%2 × %3 像素，%4 位，%5 毫秒</translation>
    </message>
    <message>
        <source>, at %1, %2 mm</source>
        <translation>，位置 %1, %2 mm</translation>
    </message>
    <message>
        <source>--specimen &apos;%1&apos; is not one of slide, grid-plate, line-scales</source>
        <translation>--specimen &apos;%1&apos; 不是 slide、grid-plate、line-scales 之一</translation>
    </message>
    <message>
        <source>--camera-seed must be a whole number from 0</source>
        <translation>--camera-seed 必须是不小于 0 的整数</translation>
    </message>
    <message>
        <source>the cameras BenchPilot can take images from, and the simulated specimens</source>
        <translation>BenchPilot 可以从中获取图像的相机，以及模拟样品</translation>
    </message>
    <message>
        <source>take one image and write it as a TIFF with where the stage stood</source>
        <translation>拍摄一张图像，连同载物台所在位置写成 TIFF 文件</translation>
    </message>
    <message>
        <source>See docs/camera.md for the sources, the image files and the simulated specimens.</source>
        <translation>图像来源、图像文件和模拟样品见 docs/camera.md。</translation>
    </message>
    <message>
        <source>--stage-errors is for the simulated stage: give --sim stage</source>
        <translation>--stage-errors 只用于仿真载物台：请给出 --sim stage</translation>
    </message>
    <message>
        <source>--stage-errors: %1</source>
        <translation>--stage-errors：%1</translation>
    </message>
    <message>
        <source>with --sim stage: the simulated stage&apos;s errors from a benchpilot.stage-errors file</source>
        <translation>与 --sim stage 一起使用：从 benchpilot.stage-errors 文件读取仿真载物台的误差</translation>
    </message>
    <message>
        <source>no 2D compensation table on the device</source>
        <translation>设备上没有二维补偿表</translation>
    </message>
    <message>
        <source>2D table of %1 × %2 nodes; %3%4%5</source>
        <translation>%1 × %2 节点的二维表；%3%4%5</translation>
    </message>
    <message>
        <source> (applied once X and Y are homed)</source>
        <translation>（X 和 Y 回零后生效）</translation>
    </message>
    <message>
        <source>give one grid map result file</source>
        <translation>请给出一个网格图结果文件</translation>
    </message>
    <message>
        <source>give the table file to write: --out FILE</source>
        <translation>请给出要写入的表文件：--out FILE</translation>
    </message>
    <message>
        <source>2D table of %1 × %2 nodes, every %3 × %4 mm from (%5, %6) mm</source>
        <translation>%1 × %2 节点的二维表，从 (%5, %6) mm 起每隔 %3 × %4 mm</translation>
    </message>
    <message>
        <source>give one 2D compensation table file</source>
        <translation>请给出一个二维补偿表文件</translation>
    </message>
    <message>
        <source>a 2D compensation table from a grid map&apos;s result file</source>
        <translation>由网格图结果文件生成二维补偿表</translation>
    </message>
    <message>
        <source>RESULT</source>
        <translation>RESULT</translation>
    </message>
    <message>
        <source>RESULT is a benchpilot.grid-map-result file; the table has a node at each of its nodes, with the X and Y corrections that put the work point on them.</source>
        <translation>RESULT 为 benchpilot.grid-map-result 文件；补偿表在其每个节点处各有一个节点，其 X、Y 修正量使工作点落在这些节点上。</translation>
    </message>
    <message>
        <source>send a 2D compensation table to the device (installed disabled)</source>
        <translation>将二维补偿表发送到设备（安装后处于禁用状态）</translation>
    </message>
    <message>
        <source>the device&apos;s 2D compensation table</source>
        <translation>设备的二维补偿表</translation>
    </message>
    <message>
        <source>enable the device&apos;s 2D compensation table</source>
        <translation>启用设备的二维补偿表</translation>
    </message>
    <message>
        <source>disable the device&apos;s 2D compensation table</source>
        <translation>禁用设备的二维补偿表</translation>
    </message>
    <message>
        <source>a 2D compensation table as CSV</source>
        <translation>将二维补偿表导出为 CSV</translation>
    </message>
    <message>
        <source>stitch needs one folder of tiles (benchpilot-cli stitch DIR --out mosaic.ome.tif)</source>
        <translation>stitch 需要一个图块文件夹（benchpilot-cli stitch DIR --out mosaic.ome.tif）</translation>
    </message>
    <message>
        <source>%1: no such folder</source>
        <translation>%1：文件夹不存在</translation>
    </message>
    <message>
        <source>--pixel-um must be above 0 and below 1000 µm (got %1)</source>
        <translation>--pixel-um 必须大于 0 且小于 1000 µm（实际为 %1）</translation>
    </message>
    <message>
        <source>--image-y must be stage-minus-y or stage-plus-y (got &apos;%1&apos;)</source>
        <translation>--image-y 必须是 stage-minus-y 或 stage-plus-y（实际为“%1”）</translation>
    </message>
    <message>
        <source>--max-shift-px must be from 1 to 10000 px (got %1)</source>
        <translation>--max-shift-px 必须在 1 到 10000 px 之间（实际为 %1）</translation>
    </message>
    <message>
        <source>--repeatability-um must be above 0 and at most 1000 µm (got %1)</source>
        <translation>--repeatability-um 必须大于 0 且不超过 1000 µm（实际为 %1）</translation>
    </message>
    <message>
        <source>--blend must be feather or overlay (got &apos;%1&apos;)</source>
        <translation>--blend 必须是 feather 或 overlay（实际为“%1”）</translation>
    </message>
    <message>
        <source>%1 holds neither a scan run log (%2) nor a TileConfiguration.txt: say where the tiles were taken with --positions</source>
        <translation>%1 中既没有扫描运行日志（%2），也没有 TileConfiguration.txt：请用 --positions 指明各图块的拍摄位置</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <source>%1 gives positions in mm: give the pixel size at the sample with --pixel-um (or the scan plan with --plan)</source>
        <translation>%1 中的位置以 mm 为单位：请用 --pixel-um 给出样品面上的像元尺寸（或用 --plan 给出扫描方案）</translation>
    </message>
    <message>
        <source>%1 names %2, which is not in the folder</source>
        <translation>%1 列出了 %2，但文件夹中没有该文件</translation>
    </message>
    <message>
        <source>%1 places %2 tiles, but the folder also holds tile images it does not name: %3. Stitch a folder of one scan, or give positions for every image.</source>
        <translation>%1 给出了 %2 个图块的位置，但文件夹中还有它未列出的图块图像：%3。请只拼接同一次扫描的文件夹，或为每幅图像给出位置。</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>%1 tiles, %2 pairs: %3 trusted, %4 rejected as outliers, %5 not trusted; %6 tiles placed by the stage
</source>
        <translation>%1 个图块，%2 对：%3 对可信，%4 对作为离群值剔除，%5 对不可信；%6 个图块按载物台位置放置
</translation>
    </message>
    <message>
        <source>correction from the stage: RMS %1 px, worst %2 px
</source>
        <translation>相对载物台位置的修正：均方根 %1 px，最大 %2 px
</translation>
    </message>
    <message>
        <source>wrote %1 (%2 × %3 px), %4 and %5 in %6 s
</source>
        <translation>已写出 %1（%2 × %3 px）、%4 和 %5，用时 %6 s
</translation>
    </message>
    <message>
        <source>stitch a folder of tiles into a pyramidal OME-TIFF mosaic</source>
        <translation>把一个图块文件夹拼接成金字塔 OME-TIFF 全景图</translation>
    </message>
    <message>
        <source>DIR</source>
        <translation>DIR</translation>
    </message>
    <message>
        <source>Registers every pair of neighbouring tiles over their expected overlap, places all tiles by weighted least squares with the stage positions as priors, and fuses them (docs/stitching.md). Positions: the scan&apos;s run log or TileConfiguration.txt in DIR, or --positions. Writes the mosaic (--out), TileConfiguration.registered.txt in DIR and a .stitch.json report beside the mosaic.</source>
        <translation>在预期重叠区内配准每一对相邻图块，以载物台位置为先验、用加权最小二乘放置全部图块，再融合成图（docs/stitching.md）。位置来自 DIR 中的扫描运行日志或 TileConfiguration.txt，或由 --positions 给出。写出全景图（--out）、DIR 中的 TileConfiguration.registered.txt，以及全景图旁的 .stitch.json 报告。</translation>
    </message>
    <message>
        <source>the folder of tiles</source>
        <translation>图块所在的文件夹</translation>
    </message>
    <message>
        <source>a USB camera through Qt Multimedia: NAME as camera list names it, NAME@WIDTHxHEIGHT for a resolution</source>
        <translation>经 Qt Multimedia 的 USB 相机：NAME 为 camera list 列出的名称，NAME@WIDTHxHEIGHT 指定分辨率</translation>
    </message>
    <message>
        <source>USB cameras: none found</source>
        <translation>USB 相机：未找到</translation>
    </message>
    <message>
        <source>USB cameras:</source>
        <translation>USB 相机：</translation>
    </message>
    <message>
        <source>, the default</source>
        <translation>，默认相机</translation>
    </message>
    <message>
        <source>no format BenchPilot can read</source>
        <translation>没有 BenchPilot 能读取的格式</translation>
    </message>
    <message>
        <source>needs --camera SOURCE (sim, sim:PATH, uvc[:NAME], command:CMD or folder:DIR; see camera list)</source>
        <translation>需要 --camera SOURCE（sim、sim:PATH、uvc[:NAME]、command:CMD 或 folder:DIR；见 camera list）</translation>
    </message>
    <message>
        <source>With --sim stage and --camera sim the simulated camera renders the specimen at the stage&apos;s true position; on benchpilot-sim&apos;s pty, --camera sim:PATH takes it from the socket that benchpilot-sim serves with --camera-socket PATH (see docs/camera.md).</source>
        <translation>使用 --sim stage 和 --camera sim 时，模拟相机按载物台的真实位置渲染样品；使用 benchpilot-sim 的 pty 时，--camera sim:PATH 从 benchpilot-sim 以 --camera-socket PATH 提供的套接字取得图像（见 docs/camera.md）。</translation>
    </message>
    <message>
        <source>--source &apos;%1&apos;: readback, gauge:PATH, manual, interferometer or camera[:SOURCE]</source>
        <translation>--source &apos;%1&apos;：应为 readback、gauge:PATH、manual、interferometer 或 camera[:SOURCE]</translation>
    </message>
    <message>
        <source>the camera %1 did not open within %2 s</source>
        <translation>相机 %1 未在 %2 秒内打开</translation>
    </message>
    <message>
        <source>--test gives the whole test: leave out --%1</source>
        <translation>--test 已给出整个测试：请去掉 --%1</translation>
    </message>
    <message>
        <source>give --pitch MM and --nodes COLUMNS,ROWS, or --test FILE</source>
        <translation>请给出 --pitch 毫米 和 --nodes 列数,行数，或 --test 文件</translation>
    </message>
    <message>
        <source>--pitch &apos;%1&apos;: one pitch in mm, or X,Y</source>
        <translation>--pitch“%1”：一个以毫米为单位的间距，或 X,Y</translation>
    </message>
    <message>
        <source>--nodes &apos;%1&apos;: two whole numbers, COLUMNS,ROWS</source>
        <translation>--nodes“%1”：两个整数，列数,行数</translation>
    </message>
    <message>
        <source>give the folder for the run: --out DIR</source>
        <translation>请给出运行文件夹：--out 目录</translation>
    </message>
    <message>
        <source><byte value="xd"/>%1 of %2 nodes   </source>
        <translation><byte value="xd"/>%2 个节点中的第 %1 个   </translation>
    </message>
    <message>
        <source>%1 holds a finished map of this test: its results follow, nothing was moved.</source>
        <translation>%1 中已有此测试完成的网格图：以下是其结果，未移动任何轴。</translation>
    </message>
    <message>
        <source>scale X %1 ppm, scale Y %2 ppm, squareness %3 µrad</source>
        <translation>X 比例误差 %1 ppm，Y 比例误差 %2 ppm，垂直度 %3 µrad</translation>
    </message>
    <message>
        <source>straightness X %1 µm, straightness Y %2 µm</source>
        <translation>X 直线度 %1 µm，Y 直线度 %2 µm</translation>
    </message>
    <message>
        <source>error RMS %1 µm, max %2 µm; residual RMS %3 µm</source>
        <translation>误差均方根 %1 µm，最大 %2 µm；残差均方根 %3 µm</translation>
    </message>
    <message>
        <source>the XY stage mapped by the camera on a grid plate: scale, squareness, straightness</source>
        <translation>用相机对准网格板测绘 XY 平台：比例误差、垂直度、直线度</translation>
    </message>
    <message>
        <source>map the stage on a grid plate with the camera</source>
        <translation>用相机在网格板上测绘平台</translation>
    </message>
    <message>
        <source>Starts at the dot nearest the image centre where the stage stands (or --start), visits the nodes row by row, each approached from below (with --bidirectional, then again in reverse order from above), finds each dot to a fraction of a pixel, and writes the readings CSV and the result JSON into --out. A run that stopped continues from its log there without reading a node twice.</source>
        <translation>从平台所在位置图像中心最近的圆点（或 --start）开始，逐行访问各节点，每个节点都从下方趋近（使用 --bidirectional 时，再按相反顺序从上方趋近），以亚像素精度找到每个圆点，并将读数 CSV 和结果 JSON 写入 --out。已停止的运行从该处的日志继续，不会重复读取任何节点。</translation>
    </message>
    <message>
        <source>the grid map&apos;s result file</source>
        <translation>网格图的结果文件</translation>
    </message>
    <message>
        <source>the 2D compensation table file</source>
        <translation>二维补偿表文件</translation>
    </message>
    <message>
        <source>needs --out PROFILE.json, the camera profile to write</source>
        <translation>需要 --out PROFILE.json，即要写入的相机配置文件</translation>
    </message>
    <message>
        <source>--step-px must be from 1 to 10000</source>
        <translation>--step-px 必须在 1 到 10000 之间</translation>
    </message>
    <message>
        <source>--steps must be a whole number from 1 to 10</source>
        <translation>--steps 必须是 1 到 10 之间的整数</translation>
    </message>
    <message>
        <source>--pixel-um must be above 0 and at most 1000</source>
        <translation>--pixel-um 必须大于 0 且不超过 1000</translation>
    </message>
    <message>
        <source>--at must be X,Y in mm (got &apos;%1&apos;)</source>
        <translation>--at 必须是以 mm 为单位的 X,Y（收到的是 &apos;%1&apos;）</translation>
    </message>
    <message>
        <source>the stage did not reach %1, %2 mm</source>
        <translation>载物台未到达 %1, %2 mm</translation>
    </message>
    <message>
        <source>image %1 of %2</source>
        <translation>第 %1 张图像，共 %2 张</translation>
    </message>
    <message>
        <source>the calibration did not finish within %1 min</source>
        <translation>标定未在 %1 分钟内完成</translation>
    </message>
    <message>
        <source>pixel %1 × %2 µm, rotation %3°, image y along stage %4; residual %5 px RMS (worst %6 px), %7 images</source>
        <translation>像素 %1 × %2 µm，旋转 %3°，图像 y 沿载物台 %4；残差 %5 px RMS（最大 %6 px），共 %7 张图像</translation>
    </message>
    <message>
        <source>The pixel size comes from the stage&apos;s own steps: it carries the stage&apos;s scale error.</source>
        <translation>像素尺寸来自载物台自身的步距：它带有载物台的标尺误差。</translation>
    </message>
    <message>
        <source>measure the camera&apos;s pixel size, rotation and mirror against the stage, and write a camera profile</source>
        <translation>相对载物台测量相机的像素尺寸、旋转和镜像，并写入相机配置文件</translation>
    </message>
    <message>
        <source>Moves the stage by ±1…±N steps along X and Y around where it stands (homed, inside its soft limits), takes an image at each, registers it against the first, returns to the start and fits the camera–stage mapping. The pixel size comes from the stage&apos;s own steps, so it carries the stage&apos;s scale error (docs/camera.md).</source>
        <translation>在载物台当前位置周围沿 X 和 Y 移动 ±1…±N 步（须已回零，且在软限位内），每步拍摄一张图像，与第一张配准，回到起点，并拟合相机–载物台映射。像素尺寸来自载物台自身的步距，因此带有载物台的标尺误差（docs/camera.md）。</translation>
    </message>
    <message>
        <source>--camera %1: the specimen, its seed and the camera&apos;s true geometry are benchpilot-sim&apos;s own (its --specimen, --camera-seed and --camera-true)</source>
        <translation>--camera %1：样品、其种子和相机的真实几何由 benchpilot-sim 自己决定（其 --specimen、--camera-seed 和 --camera-true）</translation>
    </message>
    <message>
        <source>--camera-true: &apos;%1&apos; is not pixel-um=X[:Y] (above 0), rotation-deg=D (-360 to 360) or mirror</source>
        <translation>--camera-true：&apos;%1&apos; 不是 pixel-um=X[:Y]（大于 0）、rotation-deg=D（-360 到 360）或 mirror</translation>
    </message>
    <message>
        <source>cameras: list the sources, take an image, calibrate against the stage</source>
        <translation>相机：列出图像来源，拍摄图像，相对载物台标定</translation>
    </message>
    <message>
        <source>warning: %1
</source>
        <translation>警告：%1
</translation>
    </message>
    <message>
        <source>Grid map of the XY stage</source>
        <translation>XY 平台网格图</translation>
    </message>
    <message>
        <source>--dark must be from 0 to 65535 grey levels (got %1)</source>
        <translation>--dark 必须在 0 到 65535 灰度级之间（实际为 %1）</translation>
    </message>
    <message>
        <source>--dark is the camera&apos;s offset under --flat: give the blank image with --flat</source>
        <translation>--dark 是配合 --flat 使用的相机偏置：请用 --flat 给出空白图像</translation>
    </message>
    <message>
        <source>stage model from %1 pairs: scale x %2 ppm, y %3 ppm, rotation %4 µrad, shear %5 µrad; beyond it RMS %6 px, worst %7 px
</source>
        <translation>由 %1 对拟合的载物台模型：x 比例 %2 ppm，y 比例 %3 ppm，旋转 %4 µrad，剪切 %5 µrad；模型之外 RMS %6 px，最大 %7 px
</translation>
    </message>
    <message>
        <source>Needs the stage (--sim stage or --port) homed (--home does it). The run log and TileConfiguration.txt, positions.pos and scan.csv go to --out; a run stopped part-way continues at its next tile when run again. With --camera the tiles are stitched as they come: after the last, mosaic.ome.tif, TileConfiguration.registered.txt, mosaic.stitch.json and quality-map.png are in --out (--no-stitch: not).</source>
        <translation>需要已回零（--home 可完成）的载物台（--sim stage 或 --port）。运行日志以及 TileConfiguration.txt、positions.pos 和 scan.csv 写入 --out；中途停止的运行再次运行时会从下一个图块继续。使用 --camera 时，图块边采集边拼接：最后一个图块之后，mosaic.ome.tif、TileConfiguration.registered.txt、mosaic.stitch.json 和 quality-map.png 位于 --out 中（--no-stitch：不拼接）。</translation>
    </message>
    <message>
        <source>pair %1 + %2 registered: shift %3, %4 px, score %5, %6
</source>
        <translation>图块对 %1 + %2 已配准：位移 %3, %4 px，得分 %5，%6
</translation>
    </message>
    <message>
        <source>stitching %1 failed: %2</source>
        <translation>拼接 %1 失败：%2</translation>
    </message>
    <message>
        <source>the scan is whole, but stitching it failed: %1 (benchpilot-cli stitch %2 tries again)</source>
        <translation>扫描已完整，但拼接失败：%1（benchpilot-cli stitch %2 可重试）</translation>
    </message>
    <message>
        <source>the quality map could not be written to %1: %2</source>
        <translation>无法将质量图写入 %1：%2</translation>
    </message>
    <message>
        <source>stitched live into %1: %2
</source>
        <translation>已在扫描中实时拼接到 %1：%2
</translation>
    </message>
    <message>
        <source>stitched %1: %2
</source>
        <translation>已拼接 %1：%2
</translation>
    </message>
    <message>
        <source>both directions, the map their mean; reversal max %1 µm, mean along X %2 µm, along Y %3 µm (the lost motion a 2D table cannot correct)</source>
        <translation>双向，网格图取两者的平均值；反向差最大 %1 µm，沿 X 平均 %2 µm，沿 Y 平均 %3 µm（二维补偿表无法校正的空程）</translation>
    </message>
</context>
<context>
    <name>app::cli::CliSession</name>
    <message>
        <source>--profile: %1</source>
        <translation>--profile：%1</translation>
    </message>
    <message>
        <source>--profile %1 is for the %2, but --instrument says %3</source>
        <translation>--profile %1 适用于%2，但 --instrument 指定的是%3</translation>
    </message>
    <message>
        <source>cannot connect to %1: the protocol could not be detected</source>
        <translation>无法连接到 %1：无法检测通信协议</translation>
    </message>
    <message>
        <source>cannot connect to %1: %2</source>
        <translation>无法连接到 %1：%2</translation>
    </message>
    <message>
        <source>%1 is a %2, not the %3 --instrument names</source>
        <translation>%1 是%2，不是 --instrument 指定的%3</translation>
    </message>
</context>
<context>
    <name>app::sim::PtyTransport</name>
    <message>
        <source>cannot create a pseudo-terminal: %1</source>
        <translation>无法创建伪终端：%1</translation>
    </message>
    <message>
        <source>cannot name the pseudo-terminal: %1</source>
        <translation>无法获取伪终端名称：%1</translation>
    </message>
</context>
<context>
    <name>dev</name>
    <message>
        <source>give the axis: --axis X</source>
        <translation>请指定轴：--axis X</translation>
    </message>
</context>
<context>
    <name>dev::BenchPilotClient</name>
    <message>
        <source>no link</source>
        <translation>无连接</translation>
    </message>
</context>
<context>
    <name>dev::GrblClient</name>
    <message>
        <source>no link</source>
        <translation>无链路</translation>
    </message>
    <message>
        <source>GRBL controller</source>
        <translation>GRBL 控制器</translation>
    </message>
</context>
<context>
    <name>dev::InstrumentProxy</name>
    <message>
        <source>no link</source>
        <translation>无连接</translation>
    </message>
</context>
<context>
    <name>dev::LoopbackEnd</name>
    <message>
        <source>loopback @ %1 baud</source>
        <translation>回环 @ %1 波特</translation>
    </message>
    <message>
        <source>loopback</source>
        <translation>回环</translation>
    </message>
</context>
<context>
    <name>dev::SerialTransport</name>
    <message>
        <source>%1 @ %2 baud</source>
        <translation>%1 @ %2 波特</translation>
    </message>
</context>
<context>
    <name>dev::tele::TelemetryHub</name>
    <message>
        <source>commanded</source>
        <translation>指令位置</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>实测位置</translation>
    </message>
    <message>
        <source>velocity</source>
        <translation>速度</translation>
    </message>
    <message>
        <source>following error</source>
        <translation>跟随误差</translation>
    </message>
    <message>
        <source>controller output</source>
        <translation>控制器输出</translation>
    </message>
    <message>
        <source>switches</source>
        <translation>开关</translation>
    </message>
    <message>
        <source>contour error</source>
        <translation>轮廓误差</translation>
    </message>
    <message>
        <source>controller output u</source>
        <translation>控制器输出 u</translation>
    </message>
    <message>
        <source>Instrument %1</source>
        <translation>仪器 %1</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>%1 %2 %3</source>
        <translation>%1 %2 %3</translation>
    </message>
    <message>
        <source>%1 [%2]</source>
        <translation>%1 [%2]</translation>
    </message>
</context>
<context>
    <name>files</name>
    <message>
        <source>cannot open %1: %2</source>
        <translation>无法打开 %1：%2</translation>
    </message>
    <message>
        <source>%1 is %2 MiB, more than the %3 MiB a BenchPilot file may be</source>
        <translation>%1 大小为 %2 MiB，超过 BenchPilot 文件上限 %3 MiB</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
</context>
<context>
    <name>grbl</name>
    <message>
        <source>A G-code word has no letter: every word is a letter followed by a value.</source>
        <translation>G 代码字缺少字母：每个字都是一个字母后跟数值。</translation>
    </message>
    <message>
        <source>A number is missing or is not written as a valid number.</source>
        <translation>缺少数值，或数值格式无效。</translation>
    </message>
    <message>
        <source>The &apos;$&apos; system command is not recognized or not supported.</source>
        <translation>无法识别或不支持该“$”系统命令。</translation>
    </message>
    <message>
        <source>A negative value was given where only a positive one is allowed.</source>
        <translation>在只允许正值的地方给出了负值。</translation>
    </message>
    <message>
        <source>Homing is not enabled in the controller&apos;s settings.</source>
        <translation>控制器设置中未启用回零。</translation>
    </message>
    <message>
        <source>The step pulse time is shorter than the controller allows.</source>
        <translation>步进脉冲时间短于控制器允许的最小值。</translation>
    </message>
    <message>
        <source>Reading the stored settings failed; the controller restored its defaults.</source>
        <translation>读取已存设置失败；控制器已恢复默认值。</translation>
    </message>
    <message>
        <source>This &apos;$&apos; command is only accepted while the controller is idle.</source>
        <translation>该“$”命令只能在控制器空闲时执行。</translation>
    </message>
    <message>
        <source>G-code is locked out while the controller is in alarm or jogging.</source>
        <translation>控制器处于报警或点动状态时锁定 G 代码。</translation>
    </message>
    <message>
        <source>Soft limits cannot be enabled unless homing is enabled too.</source>
        <translation>未启用回零时不能启用软限位。</translation>
    </message>
    <message>
        <source>The line is longer than the controller accepts; it was not executed.</source>
        <translation>该行超过控制器允许的长度，未执行。</translation>
    </message>
    <message>
        <source>This setting would make the step rate exceed what the controller supports.</source>
        <translation>该设置会使步进频率超过控制器所能支持的范围。</translation>
    </message>
    <message>
        <source>The safety door is open; the controller entered its door state.</source>
        <translation>安全门已打开；控制器进入安全门状态。</translation>
    </message>
    <message>
        <source>The build info or startup line is too long to be stored.</source>
        <translation>版本信息或启动行太长，无法保存。</translation>
    </message>
    <message>
        <source>The jog target lies beyond the machine travel; the jog was ignored.</source>
        <translation>点动目标超出机床行程；该点动被忽略。</translation>
    </message>
    <message>
        <source>The jog command has no &apos;=&apos; or contains G-code that jogging does not allow.</source>
        <translation>点动命令缺少“=”，或含有点动不允许的 G 代码。</translation>
    </message>
    <message>
        <source>Laser mode needs a PWM spindle output.</source>
        <translation>激光模式需要 PWM 主轴输出。</translation>
    </message>
    <message>
        <source>The controller is being reset.</source>
        <translation>控制器正在复位。</translation>
    </message>
    <message>
        <source>A value that must be above zero was zero or negative.</source>
        <translation>必须大于零的数值为零或负值。</translation>
    </message>
    <message>
        <source>The block contains a G-code command that is not supported or not valid.</source>
        <translation>程序段含有不支持或无效的 G 代码命令。</translation>
    </message>
    <message>
        <source>The block contains two commands of the same modal group.</source>
        <translation>程序段含有同一模态组的两个命令。</translation>
    </message>
    <message>
        <source>No feed rate has been set for this move.</source>
        <translation>该移动未设置进给速度。</translation>
    </message>
    <message>
        <source>This G-code command needs a whole-number value.</source>
        <translation>该 G 代码命令需要整数值。</translation>
    </message>
    <message>
        <source>Two commands in the block both need the axis words.</source>
        <translation>程序段中有两个命令都需要轴字。</translation>
    </message>
    <message>
        <source>A G-code word appears twice in the block.</source>
        <translation>程序段中某个 G 代码字出现了两次。</translation>
    </message>
    <message>
        <source>The command needs axis words, and the block has none.</source>
        <translation>该命令需要轴字，但程序段中没有。</translation>
    </message>
    <message>
        <source>The line number (N) is outside the valid range.</source>
        <translation>行号（N）超出有效范围。</translation>
    </message>
    <message>
        <source>The command is missing a required P or L value.</source>
        <translation>该命令缺少必需的 P 或 L 值。</translation>
    </message>
    <message>
        <source>The work coordinate systems G59.1, G59.2 and G59.3 are not supported.</source>
        <translation>不支持工件坐标系 G59.1、G59.2 和 G59.3。</translation>
    </message>
    <message>
        <source>G53 is only allowed with G0 or G1 motion.</source>
        <translation>G53 只能与 G0 或 G1 运动一起使用。</translation>
    </message>
    <message>
        <source>The block has axis words that no command uses.</source>
        <translation>程序段中有未被任何命令使用的轴字。</translation>
    </message>
    <message>
        <source>The arc has no axis words in the selected plane.</source>
        <translation>圆弧在所选平面内没有轴字。</translation>
    </message>
    <message>
        <source>The motion target is invalid (an impossible arc, or a probe target equal to the current position).</source>
        <translation>运动目标无效（无法实现的圆弧，或探测目标等于当前位置）。</translation>
    </message>
    <message>
        <source>The arc&apos;s radius form gives no valid geometry; use the centre (I J) form or split the arc.</source>
        <translation>圆弧的半径格式得不到有效几何；请使用圆心（I J）格式或拆分圆弧。</translation>
    </message>
    <message>
        <source>The arc in centre form has no I/J/K offset in the selected plane.</source>
        <translation>圆心格式的圆弧在所选平面内没有 I/J/K 偏移。</translation>
    </message>
    <message>
        <source>The block has value words that no command uses.</source>
        <translation>程序段中有未被任何命令使用的数值字。</translation>
    </message>
    <message>
        <source>G43.1 dynamic tool length offset was given for an axis other than the configured one.</source>
        <translation>G43.1 动态刀具长度补偿用在了配置轴以外的轴上。</translation>
    </message>
    <message>
        <source>The tool number is above the largest supported.</source>
        <translation>刀具号超过支持的最大值。</translation>
    </message>
    <message>
        <source>A value is out of range.</source>
        <translation>数值超出范围。</translation>
    </message>
    <message>
        <source>This G-code command is not allowed while a tool change is pending.</source>
        <translation>换刀待处理时不允许该 G 代码命令。</translation>
    </message>
    <message>
        <source>The spindle is not running, but the motion needs it (constant surface speed or spindle sync).</source>
        <translation>主轴未运转，但该运动需要主轴（恒线速或主轴同步）。</translation>
    </message>
    <message>
        <source>Threading needs the ZX plane.</source>
        <translation>螺纹加工需要 ZX 平面。</translation>
    </message>
    <message>
        <source>The maximum feed rate is exceeded.</source>
        <translation>超过最大进给速度。</translation>
    </message>
    <message>
        <source>The spindle speed is out of range.</source>
        <translation>主轴转速超出范围。</translation>
    </message>
    <message>
        <source>A limit switch is engaged: only homing is allowed.</source>
        <translation>限位开关已触发：只允许回零。</translation>
    </message>
    <message>
        <source>The machine must be homed before it can continue.</source>
        <translation>设备必须先回零才能继续。</translation>
    </message>
    <message>
        <source>The current tool is not set (tool changer).</source>
        <translation>未设置当前刀具（换刀装置）。</translation>
    </message>
    <message>
        <source>Two value words conflict.</source>
        <translation>两个数值字相互冲突。</translation>
    </message>
    <message>
        <source>The power-on self test failed; a hard reset is needed.</source>
        <translation>上电自检失败；需要硬复位。</translation>
    </message>
    <message>
        <source>The emergency stop is active.</source>
        <translation>急停已触发。</translation>
    </message>
    <message>
        <source>A motor driver reports a fault.</source>
        <translation>电机驱动器报告故障。</translation>
    </message>
    <message>
        <source>The setting value is out of range.</source>
        <translation>设置值超出范围。</translation>
    </message>
    <message>
        <source>This setting is not available on this controller.</source>
        <translation>该控制器没有此设置。</translation>
    </message>
    <message>
        <source>The retract position is below the drilling depth.</source>
        <translation>回退位置低于钻孔深度。</translation>
    </message>
    <message>
        <source>Two auto-squared axes cannot be homed at the same time.</source>
        <translation>两个自动找正的轴不能同时回零。</translation>
    </message>
    <message>
        <source>The coordinate system is locked.</source>
        <translation>坐标系已锁定。</translation>
    </message>
    <message>
        <source>An unexpected file demarcation was found.</source>
        <translation>发现意外的文件分界符。</translation>
    </message>
    <message>
        <source>The auxiliary port is not available.</source>
        <translation>辅助端口不可用。</translation>
    </message>
    <message>
        <source>The SD card could not be mounted.</source>
        <translation>无法挂载 SD 卡。</translation>
    </message>
    <message>
        <source>Reading a file failed.</source>
        <translation>读取文件失败。</translation>
    </message>
    <message>
        <source>A directory could not be opened.</source>
        <translation>无法打开目录。</translation>
    </message>
    <message>
        <source>The directory was not found.</source>
        <translation>未找到目录。</translation>
    </message>
    <message>
        <source>The SD card is not mounted.</source>
        <translation>SD 卡未挂载。</translation>
    </message>
    <message>
        <source>The file system is not mounted.</source>
        <translation>文件系统未挂载。</translation>
    </message>
    <message>
        <source>The file system is read-only.</source>
        <translation>文件系统为只读。</translation>
    </message>
    <message>
        <source>Bluetooth could not be started.</source>
        <translation>无法启动蓝牙。</translation>
    </message>
    <message>
        <source>An expression contains an unknown operation.</source>
        <translation>表达式含有未知运算。</translation>
    </message>
    <message>
        <source>An expression divides by zero.</source>
        <translation>表达式除以零。</translation>
    </message>
    <message>
        <source>An expression argument is too large or too small.</source>
        <translation>表达式参数过大或过小。</translation>
    </message>
    <message>
        <source>An expression argument is not valid for its operation.</source>
        <translation>表达式参数对其运算无效。</translation>
    </message>
    <message>
        <source>An expression is not valid.</source>
        <translation>表达式无效。</translation>
    </message>
    <message>
        <source>An expression gave no number (NaN or infinity).</source>
        <translation>表达式没有得到数值（NaN 或无穷大）。</translation>
    </message>
    <message>
        <source>Authentication is required.</source>
        <translation>需要身份验证。</translation>
    </message>
    <message>
        <source>Access is denied.</source>
        <translation>访问被拒绝。</translation>
    </message>
    <message>
        <source>Not allowed while a critical event is active.</source>
        <translation>存在关键事件时不允许此操作。</translation>
    </message>
    <message>
        <source>Flow statements are only allowed in a macro from the file system.</source>
        <translation>流程语句只允许出现在文件系统中的宏里。</translation>
    </message>
    <message>
        <source>The flow statement is unknown.</source>
        <translation>未知的流程语句。</translation>
    </message>
    <message>
        <source>A flow statement overflowed the stack.</source>
        <translation>流程语句导致栈溢出。</translation>
    </message>
    <message>
        <source>A flow statement ran out of memory.</source>
        <translation>流程语句耗尽了内存。</translation>
    </message>
    <message>
        <source>The file could not be opened.</source>
        <translation>无法打开文件。</translation>
    </message>
    <message>
        <source>A user-defined error occurred.</source>
        <translation>发生用户定义的错误。</translation>
    </message>
    <message>
        <source>A hard limit switch was hit. The sudden halt has probably lost the position: home again.</source>
        <translation>触发了硬限位开关。突然停止很可能丢失了位置：请重新回零。</translation>
    </message>
    <message>
        <source>A motion target lies beyond the machine travel (soft limit). The position was kept; the alarm may be unlocked.</source>
        <translation>运动目标超出机床行程（软限位）。位置已保留；可以解除报警。</translation>
    </message>
    <message>
        <source>Reset while moving. The position is probably lost: home again.</source>
        <translation>运动中被复位。位置很可能已丢失：请重新回零。</translation>
    </message>
    <message>
        <source>Probe failed: the probe was not in the expected state before the probing cycle began.</source>
        <translation>探测失败：探测循环开始前探针不在预期状态。</translation>
    </message>
    <message>
        <source>Probe failed: the probe did not touch within the programmed travel.</source>
        <translation>探测失败：在编程行程内探针未接触。</translation>
    </message>
    <message>
        <source>Homing failed: the homing cycle was reset.</source>
        <translation>回零失败：回零循环被复位。</translation>
    </message>
    <message>
        <source>Homing failed: the safety door was opened during homing.</source>
        <translation>回零失败：回零期间安全门被打开。</translation>
    </message>
    <message>
        <source>Homing failed: pulling off did not clear the limit switch. Increase the pull-off distance or check the wiring.</source>
        <translation>回零失败：回退后限位开关仍未释放。请加大回退距离或检查接线。</translation>
    </message>
    <message>
        <source>Homing failed: no limit switch was found within the search distance. Check the maximum travel, the pull-off and the wiring.</source>
        <translation>回零失败：在搜索距离内未找到限位开关。请检查最大行程、回退距离和接线。</translation>
    </message>
    <message>
        <source>The emergency stop is asserted: clear it and reset.</source>
        <translation>急停信号有效：请解除后复位。</translation>
    </message>
    <message>
        <source>Homing is required: run homing ($H) to continue.</source>
        <translation>需要回零：请执行回零（$H）后继续。</translation>
    </message>
    <message>
        <source>A limit switch is engaged: clear it before continuing.</source>
        <translation>限位开关已触发：请先解除再继续。</translation>
    </message>
    <message>
        <source>The probe protection was triggered: clear it before continuing.</source>
        <translation>探针保护已触发：请先解除再继续。</translation>
    </message>
    <message>
        <source>The spindle did not reach its speed in time: clear before continuing.</source>
        <translation>主轴未能按时达到转速：请先解除再继续。</translation>
    </message>
    <message>
        <source>Homing failed: the second switch of an auto-squared axis was not found within the search distance.</source>
        <translation>回零失败：在搜索距离内未找到自动找正轴的第二个开关。</translation>
    </message>
    <message>
        <source>The power-on self test failed.</source>
        <translation>上电自检失败。</translation>
    </message>
    <message>
        <source>Homing failed: the homing configuration is not valid.</source>
        <translation>回零失败：回零配置无效。</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>BenchPilot operator and test-bench application.</source>
        <translation>BenchPilot 操作与测试台应用程序。</translation>
    </message>
    <message>
        <source>render a screen to a PNG and exit</source>
        <translation>把一个界面渲染为 PNG 后退出</translation>
    </message>
    <message>
        <source>screen to show: jog, plots, profiles, …</source>
        <translation>要显示的界面：jog、plots、profiles……</translation>
    </message>
    <message>
        <source>screenshot: how long the simulators run first</source>
        <translation>截图：仿真器先运行多长时间</translation>
    </message>
    <message>
        <source>screenshot: home the shown instrument and move it before the picture</source>
        <translation>截图：截图前让所示仪器回零并移动</translation>
    </message>
    <message>
        <source>screenshot: jog and move the shown instrument so live plots show motion</source>
        <translation>截图：点动并移动所示仪器，使实时曲线显示运动</translation>
    </message>
    <message>
        <source>screenshot: tune the stage&apos;s X axis (relay, then a step test) on the tuning screen</source>
        <translation>截图：在整定界面整定载物台 X 轴（继电试验，然后阶跃测试）</translation>
    </message>
    <message>
        <source>screenshot: open this recipe on the Plates screen, home the analyzer and run it</source>
        <translation>截图：在孔板界面打开该方案，让分析仪回零并运行</translation>
    </message>
    <message>
        <source>language of the screens: system, en or zh_CN (default: the Language menu&apos;s choice)</source>
        <translation>界面语言：system、en 或 zh_CN（默认：“语言”菜单中的选择）</translation>
    </message>
    <message>
        <source>connect this instrument to its in-process simulator and show it (analyzer or stage; also the instrument a screenshot shows)</source>
        <translation>将该仪器连接到进程内仿真器并显示（analyzer 或 stage；也是截图显示的仪器）</translation>
    </message>
    <message>
        <source>connect to this serial port or path (e.g. benchpilot-sim&apos;s pty); the protocol is detected: BenchPilot or GRBL</source>
        <translation>连接到该串口或路径（例如 benchpilot-sim 的 pty）；自动检测协议：BenchPilot 或 GRBL</translation>
    </message>
    <message>
        <source>with --port: which instrument it is, analyzer or stage (default: what the device says; a GRBL controller: the profile&apos;s, else the analyzer)</source>
        <translation>与 --port 一起使用：它是哪台仪器，analyzer 或 stage（默认：以设备所报为准；GRBL 控制器：以配置文件为准，否则为分析仪）</translation>
    </message>
    <message>
        <source>with --port: the machine profile of a GRBL controller, a file or the name of one BenchPilot ships (stage-grbl-uno; docs/grbl.md)</source>
        <translation>与 --port 一起使用：GRBL 控制器的机器配置文件，可以是文件，也可以是 BenchPilot 自带配置的名称（stage-grbl-uno；docs/grbl.md）</translation>
    </message>
    <message>
        <source>with --port: the link speed</source>
        <translation>与 --port 一起使用：链路速率</translation>
    </message>
    <message>
        <source>where the scripting API listens (default: %1)</source>
        <translation>脚本接口的监听位置（默认：%1）</translation>
    </message>
    <message>
        <source>do not start the scripting API</source>
        <translation>不启动脚本接口</translation>
    </message>
    <message>
        <source>also serve the API as a WebSocket on 127.0.0.1:port (off by default)</source>
        <translation>同时在 127.0.0.1:端口 上以 WebSocket 提供接口（默认关闭）</translation>
    </message>
    <message>
        <source>the WebSocket&apos;s token file, 0600 (default: api.token beside the socket)</source>
        <translation>WebSocket 的令牌文件，权限 0600（默认：套接字旁的 api.token）</translation>
    </message>
    <message>
        <source>a browser Origin the WebSocket accepts (repeat for more; none by default)</source>
        <translation>WebSocket 接受的浏览器 Origin（可重复指定；默认不接受任何）</translation>
    </message>
    <message>
        <source>--instrument and --profile go with --port</source>
        <translation>--instrument 和 --profile 须与 --port 一起使用</translation>
    </message>
    <message>
        <source>--sim needs &apos;analyzer&apos; or &apos;stage&apos; (got &apos;%1&apos;)</source>
        <translation>--sim 需要 &apos;analyzer&apos; 或 &apos;stage&apos;（收到 &apos;%1&apos;）</translation>
    </message>
    <message>
        <source>--baud needs a rate of at least 1200 (got &apos;%1&apos;)</source>
        <translation>--baud 需要不低于 1200 的速率（收到 &apos;%1&apos;）</translation>
    </message>
    <message>
        <source>--instrument needs &apos;analyzer&apos; or &apos;stage&apos; (got &apos;%1&apos;)</source>
        <translation>--instrument 需要 &apos;analyzer&apos; 或 &apos;stage&apos;（收到 &apos;%1&apos;）</translation>
    </message>
    <message>
        <source>--profile: %1</source>
        <translation>--profile：%1</translation>
    </message>
    <message>
        <source>--profile is for the other instrument than --instrument names</source>
        <translation>--profile 所指的仪器与 --instrument 不同</translation>
    </message>
    <message>
        <source>--sim and --port name the same instrument</source>
        <translation>--sim 与 --port 指向同一台仪器</translation>
    </message>
    <message>
        <source>screenshot: the window&apos;s size, e.g. 1366x768 (a window that cannot shrink to it shows as a larger picture)</source>
        <translation>截图：窗口尺寸，如 1366x768（无法缩到该尺寸的窗口会得到更大的图片）</translation>
    </message>
    <message>
        <source>with --sim stage: the simulated stage&apos;s errors from a benchpilot.stage-errors file</source>
        <translation>与 --sim stage 一起使用：从 benchpilot.stage-errors 文件读取仿真载物台的误差</translation>
    </message>
    <message>
        <source>--stage-errors is for the simulated stage: give --sim stage</source>
        <translation>--stage-errors 只用于仿真载物台：请给出 --sim stage</translation>
    </message>
    <message>
        <source>--stage-errors: %1</source>
        <translation>--stage-errors：%1</translation>
    </message>
    <message>
        <source>with --sim stage: what the simulated camera sees on the stage: slide, grid-plate or line-scales</source>
        <translation>与 --sim stage 一起：模拟相机在载物台上看到的样品：slide、grid-plate 或 line-scales</translation>
    </message>
    <message>
        <source>--specimen must be slide, grid-plate or line-scales (got &apos;%1&apos;)</source>
        <translation>--specimen 必须为 slide、grid-plate 或 line-scales（收到 &apos;%1&apos;）</translation>
    </message>
</context>
<context>
    <name>sim</name>
    <message>
        <source>BenchPilot simulated instrument on a pseudo-terminal.</source>
        <translation>在伪终端上运行的 BenchPilot 模拟仪器。</translation>
    </message>
    <message>
        <source>analyzer or stage</source>
        <translation>analyzer 或 stage</translation>
    </message>
    <message>
        <source>symlink to create for the pty</source>
        <translation>为 pty 创建的符号链接</translation>
    </message>
    <message>
        <source>virtual seconds per wall-clock second; above 3 a host refreshing jogs every 50 ms trips the 200 ms jog watchdog</source>
        <translation>每个真实秒对应的虚拟秒数；超过 3 时，每 50 ms 刷新一次点动的上位机会触发 200 ms 点动看门狗</translation>
    </message>
    <message>
        <source>link speed the firmware assumes</source>
        <translation>固件假定的链路速率</translation>
    </message>
    <message>
        <source>benchpilot, grbl or grblhal</source>
        <translation>benchpilot、grbl 或 grblhal</translation>
    </message>
    <message>
        <source>--instrument must be analyzer or stage (got &apos;%1&apos;)</source>
        <translation>--instrument 必须为 analyzer 或 stage（收到 &apos;%1&apos;）</translation>
    </message>
    <message>
        <source>--protocol must be benchpilot, grbl or grblhal (got &apos;%1&apos;)</source>
        <translation>--protocol 必须为 benchpilot、grbl 或 grblhal（收到 &apos;%1&apos;）</translation>
    </message>
    <message>
        <source>--pty PATH is required</source>
        <translation>必须给出 --pty PATH</translation>
    </message>
    <message>
        <source>--time-scale must be a number in (0, 1000] (got &apos;%1&apos;)</source>
        <translation>--time-scale 必须是 (0, 1000] 范围内的数（收到 &apos;%1&apos;）</translation>
    </message>
    <message>
        <source>--baud must be at least 1200 (got &apos;%1&apos;)</source>
        <translation>--baud 必须不小于 1200（收到 &apos;%1&apos;）</translation>
    </message>
    <message>
        <source>%1 exists and is not a symlink: refusing to replace it</source>
        <translation>%1 已存在且不是符号链接：拒绝替换</translation>
    </message>
    <message>
        <source>cannot create symlink %1: %2</source>
        <translation>无法创建符号链接 %1：%2</translation>
    </message>
    <message>
        <source>symlink to create for a simulated gauge&apos;s pty</source>
        <translation>为模拟测头的 pty 创建的符号链接</translation>
    </message>
    <message>
        <source>the axis whose work point the gauge reads</source>
        <translation>测头读取其工作点的轴</translation>
    </message>
    <message>
        <source>the gauge&apos;s last digit in mm</source>
        <translation>测头的末位分辨率，mm</translation>
    </message>
    <message>
        <source>standard deviation of the gauge&apos;s noise in mm</source>
        <translation>测头噪声的标准差，mm</translation>
    </message>
    <message>
        <source>--gauge-axis: the %1 has no axis &apos;%2&apos;</source>
        <translation>--gauge-axis：%1 没有轴 &apos;%2&apos;</translation>
    </message>
    <message>
        <source>--gauge-resolution must be from 0.000001 to 0.1 mm (got &apos;%1&apos;)</source>
        <translation>--gauge-resolution 必须在 0.000001 到 0.1 mm 之间（收到 &apos;%1&apos;）</translation>
    </message>
    <message>
        <source>--gauge-noise must be from 0 to 1 mm (got &apos;%1&apos;)</source>
        <translation>--gauge-noise 必须在 0 到 1 mm 之间（收到 &apos;%1&apos;）</translation>
    </message>
    <message>
        <source>--gauge needs a path of its own, not the instrument&apos;s</source>
        <translation>--gauge 需要自己的路径，不能与仪器的相同</translation>
    </message>
    <message>
        <source>write what the firmware executed to this file when stopped (benchpilot protocol only)</source>
        <translation>停止时把固件执行过的请求写入此文件（仅限 benchpilot 协议）</translation>
    </message>
    <message>
        <source>--journal records the benchpilot protocol&apos;s requests only</source>
        <translation>--journal 只记录 benchpilot 协议的请求</translation>
    </message>
    <message>
        <source>the GRBL board has no homing switches ($22=0)</source>
        <translation>GRBL 控制板没有回零开关（$22=0）</translation>
    </message>
    <message>
        <source>--no-homing is for the GRBL personality (--protocol grbl or grblhal)</source>
        <translation>--no-homing 仅用于 GRBL 模式（--protocol grbl 或 grblhal）</translation>
    </message>
    <message>
        <source>the stage&apos;s errors from a benchpilot.stage-errors file</source>
        <translation>从 benchpilot.stage-errors 文件读取载物台的误差</translation>
    </message>
    <message>
        <source>--stage-errors is for the simulated stage (--instrument stage)</source>
        <translation>--stage-errors 只用于仿真载物台（--instrument stage）</translation>
    </message>
    <message>
        <source>serve the simulated camera on a local socket here (the camera sim:PATH)</source>
        <translation>在此本地套接字上提供模拟相机（即相机 sim:PATH）</translation>
    </message>
    <message>
        <source>with --camera-socket: what lies on the stage: slide, grid-plate or line-scales</source>
        <translation>与 --camera-socket 一起：载物台上放的样品：slide、grid-plate 或 line-scales</translation>
    </message>
    <message>
        <source>with --camera-socket: the specimen&apos;s and the noise&apos;s seed</source>
        <translation>与 --camera-socket 一起：样品和噪声的种子</translation>
    </message>
    <message>
        <source>with --camera-socket: the sensor in pixels when a request gives no camera</source>
        <translation>与 --camera-socket 一起：请求未给出相机时传感器的像素数</translation>
    </message>
    <message>
        <source>with --camera-socket: a pixel at the sample in µm when a request gives no camera</source>
        <translation>与 --camera-socket 一起：请求未给出相机时一个像素在样品上的大小（µm）</translation>
    </message>
    <message>
        <source>--camera-socket is for the simulated stage (--instrument stage)</source>
        <translation>--camera-socket 用于模拟载物台（--instrument stage）</translation>
    </message>
    <message>
        <source>--camera-socket needs a path</source>
        <translation>--camera-socket 需要一个路径</translation>
    </message>
    <message>
        <source>--camera-socket needs a path of its own, not the pty&apos;s</source>
        <translation>--camera-socket 需要自己的路径，不能与 pty 的相同</translation>
    </message>
    <message>
        <source>--specimen must be slide, grid-plate or line-scales (got &apos;%1&apos;)</source>
        <translation>--specimen 必须为 slide、grid-plate 或 line-scales（收到 &apos;%1&apos;）</translation>
    </message>
    <message>
        <source>--camera-seed must be a whole number from 0 (got &apos;%1&apos;)</source>
        <translation>--camera-seed 必须为从 0 开始的整数（收到 &apos;%1&apos;）</translation>
    </message>
    <message>
        <source>--camera-sensor must be W,H in pixels, each from 1 to %1 (got &apos;%2&apos;)</source>
        <translation>--camera-sensor 必须为以像素计的 W,H，每个从 1 到 %1（收到 &apos;%2&apos;）</translation>
    </message>
    <message>
        <source>--camera-pixel-um must be above 0 and at most %1 (got &apos;%2&apos;)</source>
        <translation>--camera-pixel-um 必须大于 0 且不超过 %1（收到 &apos;%2&apos;）</translation>
    </message>
    <message>
        <source>with --camera-socket: the camera&apos;s true geometry where it differs from what it is asked: pixel-um=X[:Y],rotation-deg=D,mirror</source>
        <translation>与 --camera-socket 一起：相机与所要求不同的真实几何：pixel-um=X[:Y],rotation-deg=D,mirror</translation>
    </message>
    <message>
        <source>--specimen, --camera-seed, --camera-sensor, --camera-pixel-um and --camera-true are for the camera socket (--camera-socket PATH)</source>
        <translation>--specimen、--camera-seed、--camera-sensor、--camera-pixel-um 和 --camera-true 用于相机套接字（--camera-socket PATH）</translation>
    </message>
    <message>
        <source>--camera-true: &apos;%1&apos; is not pixel-um=X[:Y] (above 0), rotation-deg=D (-360 to 360) or mirror</source>
        <translation>--camera-true：&apos;%1&apos; 不是 pixel-um=X[:Y]（大于 0）、rotation-deg=D（-360 到 360）或 mirror</translation>
    </message>
</context>
<context>
    <name>ui::AccuracyTestForm</name>
    <message>
        <source>Axis</source>
        <translation>轴</translation>
    </message>
    <message>
        <source>Targets</source>
        <translation>目标位置</translation>
    </message>
    <message>
        <source>From (mm)</source>
        <translation>起点 (mm)</translation>
    </message>
    <message>
        <source>To (mm)</source>
        <translation>终点 (mm)</translation>
    </message>
    <message>
        <source>Count</source>
        <translation>个数</translation>
    </message>
    <message>
        <source>Spacing</source>
        <translation>间距</translation>
    </message>
    <message>
        <source>List (mm)</source>
        <translation>列表 (mm)</translation>
    </message>
    <message>
        <source>Cycles</source>
        <translation>循环次数</translation>
    </message>
    <message>
        <source>Directions</source>
        <translation>方向</translation>
    </message>
    <message>
        <source>Overrun (mm)</source>
        <translation>越程 (mm)</translation>
    </message>
    <message>
        <source>Feed (mm/s)</source>
        <translation>进给速度 (mm/s)</translation>
    </message>
    <message>
        <source>Dwell (s)</source>
        <translation>停留时间 (s)</translation>
    </message>
    <message>
        <source>Settled within (µm)</source>
        <translation>稳定容差 (µm)</translation>
    </message>
    <message>
        <source>… for (s)</source>
        <translation>… 持续 (s)</translation>
    </message>
    <message>
        <source>Settle timeout (s)</source>
        <translation>稳定超时 (s)</translation>
    </message>
    <message>
        <source>Limit on A (mm)</source>
        <translation>A 限值 (mm)</translation>
    </message>
    <message>
        <source>Limit on R (mm)</source>
        <translation>R 限值 (mm)</translation>
    </message>
    <message>
        <source>From X (mm)</source>
        <translation>起点 X (mm)</translation>
    </message>
    <message>
        <source>From Y (mm)</source>
        <translation>起点 Y (mm)</translation>
    </message>
    <message>
        <source>To X (mm)</source>
        <translation>终点 X (mm)</translation>
    </message>
    <message>
        <source>To Y (mm)</source>
        <translation>终点 Y (mm)</translation>
    </message>
    <message>
        <source>Centre X (mm)</source>
        <translation>圆心 X (mm)</translation>
    </message>
    <message>
        <source>Centre Y (mm)</source>
        <translation>圆心 Y (mm)</translation>
    </message>
    <message>
        <source>Radius (mm)</source>
        <translation>半径 (mm)</translation>
    </message>
    <message>
        <source>Lead arc (°)</source>
        <translation>引入弧 (°)</translation>
    </message>
    <message>
        <source>Samples a turn</source>
        <translation>每周采样数</translation>
    </message>
    <message>
        <source>Limit on G (mm)</source>
        <translation>G 限值 (mm)</translation>
    </message>
    <message>
        <source>Axis test (ISO 230-2)</source>
        <translation>单轴测试（ISO 230-2）</translation>
    </message>
    <message>
        <source>Linked XY line (seed 000)</source>
        <translation>XY 联动直线（文献 000）</translation>
    </message>
    <message>
        <source>Circular test (ISO 230-4)</source>
        <translation>圆测试（ISO 230-4）</translation>
    </message>
    <message>
        <source>What kind of test to run</source>
        <translation>要运行的测试类型</translation>
    </message>
    <message>
        <source>evenly from … to</source>
        <translation>从…到…等间距</translation>
    </message>
    <message>
        <source>a list</source>
        <translation>列表</translation>
    </message>
    <message>
        <source>ISO 230-2 irregular</source>
        <translation>ISO 230-2 非等间距</translation>
    </message>
    <message>
        <source>Moves each inner target off the even grid by its own amount, so a periodic error (a screw&apos;s pitch) is not sampled at one phase</source>
        <translation>使每个内部目标位置各自偏离等间距网格一个不同的量，以免周期性误差（如丝杠螺距误差）总在同一相位被采样</translation>
    </message>
    <message>
        <source>10, 25.5, 40, …</source>
        <translation>10, 25.5, 40, …</translation>
    </message>
    <message>
        <source>both (↑ and ↓)</source>
        <translation>双向（↑ 和 ↓）</translation>
    </message>
    <message>
        <source>Unticked: every target approached from below only (ISO&apos;s unidirectional test)</source>
        <translation>不勾选：每个目标位置只从下方趋近（ISO 的单向测试）</translation>
    </message>
    <message>
        <source>How far past the end targets the axis goes, so every approach comes from its side</source>
        <translation>轴越过两端目标位置的距离，使每次趋近都从相应一侧进行</translation>
    </message>
    <message>
        <source>A reading is taken once the readback has stayed this close for the time below</source>
        <translation>位置反馈在下方设定的时间内一直保持在此范围内，才取读数</translation>
    </message>
    <message>
        <source>0: not judged</source>
        <translation>0：不评定</translation>
    </message>
    <message>
        <source>both</source>
        <translation>双向</translation>
    </message>
    <message>
        <source>counter-clockwise</source>
        <translation>逆时针</translation>
    </message>
    <message>
        <source>clockwise</source>
        <translation>顺时针</translation>
    </message>
</context>
<context>
    <name>ui::AxisRow</name>
    <message>
        <source>Plunger pump, µL</source>
        <translation>柱塞泵，µL</translation>
    </message>
    <message>
        <source>Axis %1, mm</source>
        <translation>%1 轴，mm</translation>
    </message>
    <message>
        <source>Commanded position (%1)</source>
        <translation>指令位置（%1）</translation>
    </message>
    <message>
        <source>Grating scale reading (%1)</source>
        <translation>光栅尺读数（%1）</translation>
    </message>
    <message>
        <source>Encoder reading (%1)</source>
        <translation>编码器读数（%1）</translation>
    </message>
    <message>
        <source>Homed</source>
        <translation>已回零</translation>
    </message>
    <message>
        <source>Home switch</source>
        <translation>零位开关</translation>
    </message>
    <message>
        <source>Limit switch</source>
        <translation>限位开关</translation>
    </message>
    <message>
        <source>Moving</source>
        <translation>运动中</translation>
    </message>
    <message>
        <source>Step size in %1: pick a preset or type your own</source>
        <translation>步长（%1）：选择预设值或自行输入</translation>
    </message>
    <message>
        <source>Step %1 down by the step size</source>
        <translation>%1 按步长负向步进</translation>
    </message>
    <message>
        <source>Step %1 up by the step size</source>
        <translation>%1 按步长正向步进</translation>
    </message>
    <message>
        <source>Hold to move %1 down; release to stop</source>
        <translation>按住使 %1 负向移动；松开即停</translation>
    </message>
    <message>
        <source>Hold to move %1 up; release to stop</source>
        <translation>按住使 %1 正向移动；松开即停</translation>
    </message>
    <message>
        <source>Home</source>
        <translation>回零</translation>
    </message>
    <message>
        <source>Seek the home switch and make it zero</source>
        <translation>寻找零位开关并将其设为零点</translation>
    </message>
    <message>
        <source>Zero</source>
        <translation>设零</translation>
    </message>
    <message>
        <source>Make the present position zero</source>
        <translation>把当前位置设为零点</translation>
    </message>
    <message>
        <source>target %1</source>
        <translation>目标 %1</translation>
    </message>
    <message>
        <source>Go</source>
        <translation>移动</translation>
    </message>
    <message>
        <source>Soft limits: moves beyond them are refused</source>
        <translation>软限位：超出的移动会被拒绝</translation>
    </message>
    <message>
        <source>Axis %1: &apos;%2&apos; is not a position</source>
        <translation>%1 轴：“%2”不是位置</translation>
    </message>
    <message>
        <source>Axis %1: step &apos;%2&apos; is not a positive number</source>
        <translation>%1 轴：步长“%2”不是正数</translation>
    </message>
    <message>
        <source>Homing…</source>
        <translation>正在回零…</translation>
    </message>
    <message>
        <source>Not homed: absolute moves are refused</source>
        <translation>未回零：绝对移动会被拒绝</translation>
    </message>
    <message>
        <source>Home %1 first: absolute moves need a homed axis</source>
        <translation>请先让 %1 回零：绝对移动需要已回零的轴</translation>
    </message>
    <message>
        <source>Move %1 to the target (absolute)</source>
        <translation>把 %1 移到目标（绝对位置）</translation>
    </message>
    <message>
        <source>Step %1</source>
        <translation>%1 步长</translation>
    </message>
    <message>
        <source>Target %1</source>
        <translation>%1 目标</translation>
    </message>
    <message>
        <source>Axis %1: %2</source>
        <translation>%1 轴：%2</translation>
    </message>
    <message>
        <source>Unknown: the instrument is not connected</source>
        <translation>未知：仪器未连接</translation>
    </message>
    <message>
        <source>The last reading before the link went down, not where the axis is now</source>
        <translation>链路断开前的最后读数，并非该轴现在的位置</translation>
    </message>
</context>
<context>
    <name>ui::CalibrationPanel</name>
    <message>
        <source>Slot</source>
        <translation>板位</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>拟合</translation>
    </message>
    <message>
        <source>offset, rotation, scale</source>
        <translation>平移、旋转、比例</translation>
    </message>
    <message>
        <source>offset, rotation, scale per axis</source>
        <translation>平移、旋转、各轴比例</translation>
    </message>
    <message>
        <source>Three points fit any affine map exactly, so a restricted model is fitted by least squares: its residual shows a well taught off centre. One scale (the default) leaves two checks; a scale per axis leaves one.</source>
        <translation>三个点能精确确定任意仿射变换，因此这里用最小二乘法拟合一个受限模型：其残差能揭示示教时偏离中心的孔。单一比例（默认）留有两个校验量；各轴单独比例则留有一个。</translation>
    </message>
    <message>
        <source>For each well: &lt;b&gt;Go near&lt;/b&gt; (the tip rises, then moves over the well&apos;s expected place), lower it and centre it with the arrows, then &lt;b&gt;Record&lt;/b&gt;.</source>
        <translation>对每个孔：点击&lt;b&gt;移近&lt;/b&gt;（加样针先抬起，再移到该孔预期位置的上方），降下加样针并用方向键对中，然后点击&lt;b&gt;记录&lt;/b&gt;。</translation>
    </message>
    <message>
        <source>Well</source>
        <translation>孔</translation>
    </message>
    <message>
        <source>Expected (mm)</source>
        <translation>预期位置 (mm)</translation>
    </message>
    <message>
        <source>Taught (mm)</source>
        <translation>示教位置 (mm)</translation>
    </message>
    <message>
        <source>Residual (mm)</source>
        <translation>残差 (mm)</translation>
    </message>
    <message>
        <source>Jog</source>
        <translation>点动</translation>
    </message>
    <message>
        <source>Save calibration</source>
        <translation>保存校准</translation>
    </message>
    <message>
        <source>Keep this fit for the slot: recipes on it use the taught positions from now on, between runs too</source>
        <translation>为该板位保留此拟合：此后该板位上的方案都使用示教位置，跨次运行也有效</translation>
    </message>
    <message>
        <source>Forget (use nominal)</source>
        <translation>清除（用名义位置）</translation>
    </message>
    <message>
        <source>Slot %1 is calibrated (%2, taught on %3): largest residual %4 mm. Teach again to replace it.</source>
        <translation>板位 %1 已校准（%2，示教于 %3）：最大残差 %4 mm。重新示教即可替换。</translation>
    </message>
    <message>
        <source>Slot %1 is not calibrated: recipes use its nominal place. Teach it on a %2.</source>
        <translation>板位 %1 未校准：方案使用其名义位置。请放上%2进行示教。</translation>
    </message>
    <message>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <source>Go near</source>
        <translation>移近</translation>
    </message>
    <message>
        <source>Raise the tip to the slot&apos;s safe height, then move over where %1 is expected</source>
        <translation>将加样针抬到该板位的安全高度，再移到 %1 预期位置的上方</translation>
    </message>
    <message>
        <source>Record</source>
        <translation>记录</translation>
    </message>
    <message>
        <source>Take the tip&apos;s position now as the centre of %1</source>
        <translation>将加样针的当前位置记为 %1 的中心</translation>
    </message>
    <message>
        <source>Record all three wells to see the fit.</source>
        <translation>记录全部三个孔后即可看到拟合结果。</translation>
    </message>
    <message>
        <source>the analyzer is not connected</source>
        <translation>分析仪未连接</translation>
    </message>
    <message>
        <source>home the analyzer before teaching: the wells&apos; places are absolute</source>
        <translation>示教前请先让分析仪回零：孔的位置是绝对坐标</translation>
    </message>
    <message>
        <source>Move the tip over %1 of slot %2 at (%3, %4) mm, %5 mm away? It rises to Z %6 mm first.</source>
        <translation>将加样针移到板位 %2 中 %1 的上方（%3, %4）mm，距离 %5 mm？加样针会先抬到 Z %6 mm。</translation>
    </message>
    <message>
        <source>home the analyzer before teaching</source>
        <translation>示教前请先让分析仪回零</translation>
    </message>
    <message>
        <source>No fit: %1</source>
        <translation>无法拟合：%1</translation>
    </message>
    <message>
        <source>Offset (%1, %2) mm, rotation %3°, scale %4 × %5; residual largest %6 mm, rms %7 mm (warning above %8 mm).</source>
        <translation>平移（%1, %2）mm，旋转 %3°，比例 %4 × %5；残差最大 %6 mm，均方根 %7 mm（超过 %8 mm 时警告）。</translation>
    </message>
</context>
<context>
    <name>ui::CalibrationScreen</name>
    <message>
        <source>Name the gauge&apos;s port (or sim for the simulator&apos;s gauge).</source>
        <translation>请指定测头的端口（仿真器的测头填 sim）。</translation>
    </message>
    <message>
        <source>There is no way to open a gauge here.</source>
        <translation>此处无法打开测头。</translation>
    </message>
    <message>
        <source>simulated gauge</source>
        <translation>模拟测头</translation>
    </message>
    <message>
        <source>%1

Keep that log aside and start this test afresh?</source>
        <translation>%1

将该日志另存，并重新开始本测试？</translation>
    </message>
    <message>
        <source>The test takes about %1 (%2 readings). The axes move on their own until it ends. Run it?</source>
        <translation>测试约需 %1（%2 个读数）。测试结束前各轴会自动运动。是否运行？</translation>
    </message>
    <message>
        <source>Reading %1 of %2: %3%4, cycle %5. What does the indicator show?</source>
        <translation>第 %1/%2 个读数：%3%4，第 %5 次循环。千分表显示多少？</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a reading: type the indicator&apos;s value in mm.</source>
        <translation>“%1”不是读数：请输入千分表的示值，单位 mm。</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a reading here: type one value per axis, in mm.</source>
        <translation>“%1”在此不是有效读数：请为每个轴输入一个值，单位 mm。</translation>
    </message>
    <message>
        <source>Linked XY line: contour error A↑ %1 µm, R↑ %2 µm (%3 readings).</source>
        <translation>XY 联动直线：轮廓误差 A↑ %1 µm，R↑ %2 µm（%3 个读数）。</translation>
    </message>
    <message>
        <source>The test is done: results in %1.</source>
        <translation>测试完成：结果保存在 %1。</translation>
    </message>
    <message>
        <source>G, %1</source>
        <translation>G，%1</translation>
    </message>
    <message>
        <source>radial deviation, %1</source>
        <translation>径向偏差，%1</translation>
    </message>
    <message>
        <source>G(b)</source>
        <translation>G(b)</translation>
    </message>
    <message>
        <source>H hysteresis</source>
        <translation>H 圆滞后</translation>
    </message>
    <message>
        <source>Circular test, radius %1</source>
        <translation>圆测试，半径 %1</translation>
    </message>
    <message>
        <source>The circular test is done: report %1.</source>
        <translation>圆测试完成：报告见 %1。</translation>
    </message>
    <message>
        <source>No axis test has finished yet.</source>
        <translation>尚无已完成的单轴测试。</translation>
    </message>
    <message>
        <source>Run an axis test first: its fit is what is saved</source>
        <translation>请先运行单轴测试：保存的是它的拟合结果</translation>
    </message>
    <message>
        <source>Run an axis test first</source>
        <translation>请先运行单轴测试</translation>
    </message>
    <message>
        <source>pass</source>
        <translation>合格</translation>
    </message>
    <message>
        <source>FAIL</source>
        <translation>不合格</translation>
    </message>
    <message>
        <source>Axis %1 from %2: no limits given, not judged.</source>
        <translation>%1 轴（测量基准：%2）：未给出限值，不评定。</translation>
    </message>
    <message>
        <source>Axis %1 from %2: PASS.</source>
        <translation>%1 轴（测量基准：%2）：合格。</translation>
    </message>
    <message>
        <source>Axis %1 from %2: FAIL.</source>
        <translation>%1 轴（测量基准：%2）：不合格。</translation>
    </message>
    <message>
        <source>Writes the fitted compensation as a file (*.compensation.json)</source>
        <translation>将拟合得到的补偿写入文件（*.compensation.json）</translation>
    </message>
    <message>
        <source>The report of the latest run, written into its folder</source>
        <translation>最近一次运行的报告，写入其文件夹</translation>
    </message>
    <message>
        <source>Run the same axis test again after enabling the compensation: the two runs are compared here.</source>
        <translation>启用补偿后再运行一次相同的单轴测试：两次运行的结果在此对比。</translation>
    </message>
    <message>
        <source>Axis %1: A %2 µm before, %3 µm after%4.</source>
        <translation>%1 轴：A 补偿前 %2 µm，补偿后 %3 µm%4。</translation>
    </message>
    <message>
        <source>: %1 times better</source>
        <translation>，改善倍数 %1</translation>
    </message>
    <message>
        <source>Positioning accuracy of axis %1</source>
        <translation>%1 轴定位精度</translation>
    </message>
    <message>
        <source>Report written: %1</source>
        <translation>报告已生成：%1</translation>
    </message>
    <message>
        <source>The gauge&apos;s serial port (9600 Bd, 8N1); sim reads the simulator&apos;s gauge</source>
        <translation>测头的串口（9600 Bd，8N1）；填 sim 则读取仿真器的测头</translation>
    </message>
    <message>
        <source>Used when the readings come from a gauge</source>
        <translation>读数来自测头时使用</translation>
    </message>
    <message>
        <source>A circular test samples the readback along the path</source>
        <translation>圆测试沿路径采样位置反馈</translation>
    </message>
    <message>
        <source>The readback is what the position loop closes on: it cannot see the work point&apos;s error. A gauge or an interferometer at the work point can.</source>
        <translation>位置反馈是位置环闭环所依据的量，看不到工作点处的误差；安装在工作点处的测头或干涉仪才能测到。</translation>
    </message>
    <message>
        <source>A test is running.</source>
        <translation>测试正在运行。</translation>
    </message>
    <message>
        <source>Opening the gauge&apos;s port…</source>
        <translation>正在打开测头的端口…</translation>
    </message>
    <message>
        <source>No instrument.</source>
        <translation>没有仪器。</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>继续</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>运行</translation>
    </message>
    <message>
        <source>Run the test, or go on from where it stopped (Ctrl+R)</source>
        <translation>运行测试，或从停止处继续（Ctrl+R）</translation>
    </message>
    <message>
        <source>Stop after the reading in progress (Ctrl+P)</source>
        <translation>当前读数完成后暂停（Ctrl+P）</translation>
    </message>
    <message>
        <source>Nothing is running.</source>
        <translation>没有正在运行的测试。</translation>
    </message>
    <message>
        <source>Stop the axes now; Run goes on at the next reading later (Ctrl+.)</source>
        <translation>立即停止各轴；之后按“运行”从下一个读数继续（Ctrl+.）</translation>
    </message>
    <message>
        <source>Circle %1 of %2, about %3 left.</source>
        <translation>第 %1/%2 圈，约剩 %3。</translation>
    </message>
    <message>
        <source>The circular test is done.</source>
        <translation>圆测试完成。</translation>
    </message>
    <message>
        <source>Reading %1 of %2, about %3 left%4.</source>
        <translation>第 %1/%2 个读数，约剩 %3%4。</translation>
    </message>
    <message>
        <source> (pausing after this reading)</source>
        <translation>（本读数完成后暂停）</translation>
    </message>
    <message>
        <source>Done: %1 readings.</source>
        <translation>完成：共 %1 个读数。</translation>
    </message>
    <message>
        <source>Define a test, pick where the readings come from, and run it.</source>
        <translation>定义测试，选择读数来源，然后运行。</translation>
    </message>
    <message>
        <source>Instrument</source>
        <translation>仪器</translation>
    </message>
    <message>
        <source>Open an accuracy test</source>
        <translation>打开精度测试</translation>
    </message>
    <message>
        <source>Accuracy tests (*.accuracy-test.json)</source>
        <translation>精度测试文件 (*.accuracy-test.json)</translation>
    </message>
    <message>
        <source>Save the accuracy test</source>
        <translation>保存精度测试</translation>
    </message>
    <message>
        <source>From</source>
        <translation>读数来源</translation>
    </message>
    <message>
        <source>Gauge port</source>
        <translation>测头端口</translation>
    </message>
    <message>
        <source>Folder for the run&apos;s log, readings and report</source>
        <translation>存放运行日志、读数和报告的文件夹</translation>
    </message>
    <message>
        <source>Folder</source>
        <translation>文件夹</translation>
    </message>
    <message>
        <source>Test</source>
        <translation>测试</translation>
    </message>
    <message>
        <source>Readings</source>
        <translation>读数</translation>
    </message>
    <message>
        <source>The instrument the test runs on</source>
        <translation>运行测试的仪器</translation>
    </message>
    <message>
        <source>Open…</source>
        <translation>打开…</translation>
    </message>
    <message>
        <source>Save…</source>
        <translation>保存…</translation>
    </message>
    <message>
        <source>the instrument&apos;s readback</source>
        <translation>仪器的位置反馈</translation>
    </message>
    <message>
        <source>a gauge on a serial port</source>
        <translation>串口测头</translation>
    </message>
    <message>
        <source>typed at each stop (dial indicator)</source>
        <translation>每个测点手动输入（千分表）</translation>
    </message>
    <message>
        <source>laser interferometer (import afterwards)</source>
        <translation>激光干涉仪（事后导入）</translation>
    </message>
    <message>
        <source>/dev/ttyUSB1, or sim for the simulator&apos;s gauge</source>
        <translation>/dev/ttyUSB1，或填 sim 使用仿真器的测头</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>浏览…</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <source>Abort</source>
        <translation>中止</translation>
    </message>
    <message>
        <source>Enter</source>
        <translation>确定</translation>
    </message>
    <message>
        <source>reading in mm, e.g. 40.0012</source>
        <translation>读数，单位 mm，例如 40.0012</translation>
    </message>
    <message>
        <source>Live</source>
        <translation>实时</translation>
    </message>
    <message>
        <source>Results</source>
        <translation>结果</translation>
    </message>
    <message>
        <source>Compensation</source>
        <translation>补偿</translation>
    </message>
    <message>
        <source>Before / after</source>
        <translation>补偿前后</translation>
    </message>
    <message>
        <source>Circle</source>
        <translation>圆测试</translation>
    </message>
    <message>
        <source>figure</source>
        <translation>指标</translation>
    </message>
    <message>
        <source>µm</source>
        <translation>µm</translation>
    </message>
    <message>
        <source>limit (µm)</source>
        <translation>限值 (µm)</translation>
    </message>
    <message>
        <source>verdict</source>
        <translation>判定</translation>
    </message>
    <message>
        <source>before (µm)</source>
        <translation>补偿前 (µm)</translation>
    </message>
    <message>
        <source>after (µm)</source>
        <translation>补偿后 (µm)</translation>
    </message>
    <message>
        <source>improvement</source>
        <translation>改善倍数</translation>
    </message>
    <message>
        <source>Save compensation…</source>
        <translation>保存补偿…</translation>
    </message>
    <message>
        <source>Write PDF report</source>
        <translation>生成 PDF 报告</translation>
    </message>
    <message>
        <source>The test cannot be opened:
%1</source>
        <translation>无法打开该测试：
%1</translation>
    </message>
    <message>
        <source>Opened %1.</source>
        <translation>已打开 %1。</translation>
    </message>
    <message>
        <source>Saved %1.</source>
        <translation>已保存 %1。</translation>
    </message>
    <message>
        <source>Save the compensation</source>
        <translation>保存补偿</translation>
    </message>
    <message>
        <source>Compensations (*.compensation.json)</source>
        <translation>补偿文件 (*.compensation.json)</translation>
    </message>
    <message>
        <source>A test is running: the test on screen stays until it has finished or been aborted.</source>
        <translation>测试正在运行：屏幕上的测试会保留，直到它完成或被中止。</translation>
    </message>
    <message>
        <source>The run&apos;s target sequence</source>
        <translation>该次运行的目标位置序列</translation>
    </message>
    <message>
        <source>Target sequences (*.targets.csv)</source>
        <translation>目标位置序列 (*.targets.csv)</translation>
    </message>
    <message>
        <source>The interferometer&apos;s CSV export of that run</source>
        <translation>该次运行的激光干涉仪 CSV 导出文件</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
    <message>
        <source>A test is running: import the capture when it has finished.</source>
        <translation>测试正在运行：请在其结束后再导入采集数据。</translation>
    </message>
    <message>
        <source>Only an axis test&apos;s capture can be imported: show the axis test it belongs to.</source>
        <translation>只能导入单轴测试的采集数据：请先显示该数据所属的单轴测试。</translation>
    </message>
    <message>
        <source>The target sequence cannot be read:
%1</source>
        <translation>无法读取目标位置序列：
%1</translation>
    </message>
    <message>
        <source>The capture does not match the run&apos;s stops, so nothing was imported:
%1</source>
        <translation>采集数据与该次运行的停留点不符，未导入任何数据：
%1</translation>
    </message>
    <message>
        <source>The imported readings cannot be evaluated:
%1</source>
        <translation>导入的读数无法评定：
%1</translation>
    </message>
    <message>
        <source>%1 exists already. Replace it with the readings of this capture?</source>
        <translation>%1 已存在。要用本次采集的读数替换它吗？</translation>
    </message>
    <message numerus="yes">
        <source>Imported %n reading(s) from %1: results in %2.</source>
        <translation>
            <numerusform>已从 %1 导入 %n 个读数：结果位于 %2。</numerusform>
        </translation>
    </message>
    <message>
        <source>Every stop is visited. Capture with the interferometer, then import its export against %1 (Import capture…).</source>
        <translation>所有停留点均已到达。请用激光干涉仪采集，然后将其导出文件按 %1 导入（导入采集数据…）。</translation>
    </message>
    <message>
        <source>Match an interferometer&apos;s CSV export to a run&apos;s target sequence and evaluate it against the axis test on screen</source>
        <translation>将激光干涉仪导出的 CSV 与某次运行的目标位置序列相匹配，并按屏幕上的单轴测试进行评定</translation>
    </message>
    <message>
        <source>Import capture…</source>
        <translation>导入采集数据…</translation>
    </message>
    <message>
        <source>%1 is not the run of the axis test on screen, so nothing was imported: %2. Open the test the capture belongs to, then import again.</source>
        <translation>%1 不是屏幕上这项单轴测试的运行序列，因此未导入任何数据：%2。请打开该采集数据所属的测试，再重新导入。</translation>
    </message>
    <message>
        <source>Paused after %1 of %2 readings.</source>
        <translation>已取得 %1/%2 个读数，已暂停。</translation>
    </message>
    <message>
        <source>Stopped after %1 of %2 readings: %3</source>
        <translation>已取得 %1/%2 个读数，已停止：%3</translation>
    </message>
    <message>
        <source>The test is not saved: %1</source>
        <translation>测试未保存：%1</translation>
    </message>
    <message>
        <source>%1 holds a finished run of this test. Run the test again into %2? Both runs are kept, and Before / after compares the new one with this one.</source>
        <translation>%1 中已有此测试完成的一次运行。要在 %2 中再运行一次此测试吗？两次运行都会保留，“补偿前后”会把新的一次与这一次比较。</translation>
    </message>
    <message>
        <source>the camera reading a glass scale</source>
        <translation>相机读取玻璃线纹尺</translation>
    </message>
    <message>
        <source>Open a camera first, on the Scan or Jog screen&apos;s Camera tab, with the glass scale under it (on the simulator: the sim camera, with benchpilot started with --specimen line-scales).</source>
        <translation>请先在扫描或点动页的“相机”选项卡中打开相机，并把玻璃线纹尺放在其下（模拟器：sim 相机，启动 benchpilot 时加 --specimen line-scales）。</translation>
    </message>
    <message>
        <source>Grid map</source>
        <translation>网格图</translation>
    </message>
</context>
<context>
    <name>ui::CameraCalibrationPanel</name>
    <message>
        <source>Save the camera profile</source>
        <translation>保存相机配置文件</translation>
    </message>
    <message>
        <source>Camera profiles (*.camera-profile.json);;JSON (*.json)</source>
        <translation>相机配置文件 (*.camera-profile.json);;JSON (*.json)</translation>
    </message>
    <message>
        <source>Camera calibration: %1</source>
        <translation>相机标定：%1</translation>
    </message>
    <message>
        <source>Calibrate the camera: the stage moves by steps of %1 px along X and Y around where it stands (%2 images) and comes back. Nothing may touch the stage meanwhile. Start?</source>
        <translation>标定相机：载物台将在当前位置周围沿 X 和 Y 按 %1 px 的步距移动（%2 张图像），然后返回。期间不得触碰载物台。开始吗？</translation>
    </message>
    <message>
        <source>Calibrating the camera: image %1 of %2…</source>
        <translation>正在标定相机：第 %1 张图像，共 %2 张…</translation>
    </message>
    <message>
        <source>Camera calibration stopped: %1</source>
        <translation>相机标定已停止：%1</translation>
    </message>
    <message>
        <source>Pixel %1 × %2 µm, rotation %3°, image y along stage %4; residual %5 px RMS (worst %6 px), back at the start within %7 px.</source>
        <translation>像素 %1 × %2 µm，旋转 %3°，图像 y 沿载物台 %4；残差 %5 px RMS（最大 %6 px），返回起点误差在 %7 px 以内。</translation>
    </message>
    <message>
        <source>+Y (mirrored)</source>
        <translation>+Y（镜像）</translation>
    </message>
    <message>
        <source>−Y</source>
        <translation>−Y</translation>
    </message>
    <message>
        <source>The pixel size comes from the stage&apos;s own steps: it carries the stage&apos;s scale error.</source>
        <translation>像素尺寸来自载物台自身的步距：它带有载物台的标尺误差。</translation>
    </message>
    <message>
        <source>Camera profile saved to %1</source>
        <translation>相机配置文件已保存到 %1</translation>
    </message>
    <message>
        <source>Calibrate camera…</source>
        <translation>标定相机…</translation>
    </message>
    <message>
        <source>Move the stage by known steps, register the images and measure the camera&apos;s pixel size, rotation and mirror</source>
        <translation>按已知步距移动载物台，配准图像，测量相机的像素尺寸、旋转和镜像</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>Save as profile…</source>
        <translation>另存为配置文件…</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
</context>
<context>
    <name>ui::CameraPanel</name>
    <message>
        <source>Save the snapped image</source>
        <translation>保存拍摄的图像</translation>
    </message>
    <message>
        <source>Open a camera before snapping.</source>
        <translation>拍摄前请先打开相机。</translation>
    </message>
    <message>
        <source>A snap is still being taken.</source>
        <translation>上一张图像仍在拍摄中。</translation>
    </message>
    <message>
        <source>The snap was not taken: %1</source>
        <translation>未拍摄图像：%1</translation>
    </message>
    <message>
        <source>The snap was not saved to %1: %2</source>
        <translation>图像未保存到 %1：%2</translation>
    </message>
    <message>
        <source>Snapped %1.</source>
        <translation>已拍摄 %1。</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>打开</translation>
    </message>
    <message>
        <source>Open: %1</source>
        <translation>已打开：%1</translation>
    </message>
    <message>
        <source>Opening %1…</source>
        <translation>正在打开 %1…</translation>
    </message>
    <message>
        <source>Closed</source>
        <translation>已关闭</translation>
    </message>
    <message>
        <source>Opening the camera…</source>
        <translation>正在打开相机…</translation>
    </message>
    <message>
        <source>No picture: open a camera.</source>
        <translation>无图像：请打开相机。</translation>
    </message>
    <message>
        <source>This source gives no live picture: each snap is shown here.</source>
        <translation>此来源没有实时图像：每次拍摄的图像显示在这里。</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>相机</translation>
    </message>
    <message>
        <source>List the cameras again</source>
        <translation>重新列出相机</translation>
    </message>
    <message>
        <source>Exposure</source>
        <translation>曝光</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>Exposure time, where the camera lets it be set</source>
        <translation>曝光时间（相机允许设置时）</translation>
    </message>
    <message>
        <source>Snap</source>
        <translation>拍摄</translation>
    </message>
    <message>
        <source>TIFF images (*.tif *.tiff)</source>
        <translation>TIFF 图像 (*.tif *.tiff)</translation>
    </message>
    <message>
        <source>Take one image and save it as a TIFF with the stage position in it (16-bit grey stays 16-bit) (%1)</source>
        <translation>拍摄一张图像并保存为含载物台位置的 TIFF（16 位灰度保持 16 位）（%1）</translation>
    </message>
    <message>
        <source>sim: the simulated camera; sim:PATH: the one benchpilot-sim serves at PATH (--camera-socket); uvc:NAME: a USB camera; command:CMD: runs CMD for each image ({file} is where it writes); folder:DIR: takes the next new file in DIR</source>
        <translation>sim：模拟相机；sim:PATH：benchpilot-sim 在 PATH 提供的模拟相机（--camera-socket）；uvc:NAME：USB 相机；command:CMD：每张图像运行一次 CMD（{file} 是它写入的位置）；folder:DIR：取 DIR 中的下一个新文件</translation>
    </message>
    <message>
        <source>No picture: %1</source>
        <translation>无图像：%1</translation>
    </message>
    <message>
        <source>Waiting for the first picture…</source>
        <translation>正在等待第一幅图像…</translation>
    </message>
</context>
<context>
    <name>ui::CameraSession</name>
    <message>
        <source>The camera is taking a scan&apos;s tiles: pause or abort the scan before changing it.</source>
        <translation>相机正在拍摄扫描的图块：请先暂停或中止扫描再更换相机。</translation>
    </message>
    <message>
        <source>Camera %1: this build cannot open it.</source>
        <translation>相机 %1：此版本无法打开它。</translation>
    </message>
    <message>
        <source>Camera %1: %2</source>
        <translation>相机 %1：%2</translation>
    </message>
    <message>
        <source>The camera is taking a scan&apos;s tiles: pause or abort the scan before closing it.</source>
        <translation>相机正在拍摄扫描的图块：请先暂停或中止扫描再关闭相机。</translation>
    </message>
</context>
<context>
    <name>ui::ChannelPicker</name>
    <message>
        <source>Channels of</source>
        <translation>通道所属</translation>
    </message>
    <message>
        <source>The plot whose channels are ticked below; clicking a plot also chooses it</source>
        <translation>下方勾选的通道所属的曲线图；点击曲线图也可选中它</translation>
    </message>
    <message>
        <source>Channel</source>
        <translation>通道</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <source>Plot %1</source>
        <translation>曲线图 %1</translation>
    </message>
</context>
<context>
    <name>ui::ConnectionBar</name>
    <message>
        <source>Link state</source>
        <translation>连接状态</translation>
    </message>
    <message>
        <source>Look for serial ports again</source>
        <translation>重新查找串口</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>连接</translation>
    </message>
    <message>
        <source>Simulator</source>
        <translation>仿真器</translation>
    </message>
    <message>
        <source>%1 (not found)</source>
        <translation>%1（未找到）</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>断开</translation>
    </message>
    <message>
        <source>port or path</source>
        <translation>端口或路径</translation>
    </message>
    <message>
        <source>Default wiring</source>
        <translation>默认接线</translation>
    </message>
    <message>
        <source>Open a profile file…</source>
        <translation>打开配置文件…</translation>
    </message>
    <message>
        <source>Disconnect to change the connection.</source>
        <translation>断开连接后才能更改连接设置。</translation>
    </message>
    <message>
        <source>The simulated instrument, a serial port, or a path typed in (e.g. the pty benchpilot-sim serves); the protocol is detected when it connects: BenchPilot or GRBL</source>
        <translation>模拟仪器、串口或手动输入的路径（例如 benchpilot-sim 提供的 pty）；连接时自动检测协议：BenchPilot 或 GRBL</translation>
    </message>
    <message>
        <source>Baud rate (8N1); GRBL boards usually run at 115200</source>
        <translation>波特率（8N1）；GRBL 控制板通常为 115200</translation>
    </message>
    <message>
        <source>Machine profile: how a GRBL controller is wired to this instrument (axes, pump, trigger output, status rate). Default wiring: each axis on the GRBL axis of its letter, the analyzer&apos;s pump on A at 1 µL per mm, no trigger</source>
        <translation>机器配置：GRBL 控制器与本仪器的接线方式（轴、泵、触发输出、状态刷新率）。默认接线：各轴接同名 GRBL 轴，分析仪的泵接 A 轴，每 mm 1 µL，无触发输出</translation>
    </message>
    <message>
        <source>Machine profile %1</source>
        <translation>机器配置 %1</translation>
    </message>
    <message>
        <source>%1 — serial number %2</source>
        <translation>%1 — 序列号 %2</translation>
    </message>
    <message>
        <source>%1 — %2, serial number %3</source>
        <translation>%1 — %2，序列号 %3</translation>
    </message>
</context>
<context>
    <name>ui::ContourPlot</name>
    <message>
        <source>contour error</source>
        <translation>轮廓误差</translation>
    </message>
    <message>
        <source>largest</source>
        <translation>最大值</translation>
    </message>
    <message>
        <source>distance along the path (mm)</source>
        <translation>沿路径距离 (mm)</translation>
    </message>
    <message>
        <source>contour error (µm)</source>
        <translation>轮廓误差 (µm)</translation>
    </message>
</context>
<context>
    <name>ui::CursorReadout</name>
    <message>
        <source>Channel</source>
        <translation>通道</translation>
    </message>
    <message>
        <source>A</source>
        <translation>A</translation>
    </message>
    <message>
        <source>B</source>
        <translation>B</translation>
    </message>
    <message>
        <source>Δ (B − A)</source>
        <translation>Δ (B − A)</translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>时间 (s)</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>—</source>
        <translation>—</translation>
    </message>
</context>
<context>
    <name>ui::DeviationPlot</name>
    <message>
        <source>target (mm)</source>
        <translation>目标位置 (mm)</translation>
    </message>
    <message>
        <source>deviation (µm)</source>
        <translation>偏差 (µm)</translation>
    </message>
    <message>
        <source>before (mean)</source>
        <translation>补偿前（平均值）</translation>
    </message>
    <message>
        <source>↑ mean ± 2s</source>
        <translation>↑ 平均值 ± 2s</translation>
    </message>
    <message>
        <source>↓ mean ± 2s</source>
        <translation>↓ 平均值 ± 2s</translation>
    </message>
    <message>
        <source>↑ readings</source>
        <translation>↑ 读数</translation>
    </message>
    <message>
        <source>↓ readings</source>
        <translation>↓ 读数</translation>
    </message>
</context>
<context>
    <name>ui::EventLog</name>
    <message>
        <source>Time</source>
        <translation>时间</translation>
    </message>
    <message>
        <source>Instrument</source>
        <translation>仪器</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>轴</translation>
    </message>
    <message>
        <source>Event</source>
        <translation>事件</translation>
    </message>
    <message>
        <source>Details</source>
        <translation>详情</translation>
    </message>
    <message>
        <source>Stage</source>
        <translation>载物台</translation>
    </message>
    <message>
        <source>Analyzer</source>
        <translation>分析仪</translation>
    </message>
    <message>
        <source>event %1</source>
        <translation>事件 %1</translation>
    </message>
    <message>
        <source>segment %1</source>
        <translation>第 %1 段</translation>
    </message>
    <message>
        <source>at %1 %2</source>
        <translation>位于 %1 %2</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <comment>an event&apos;s detail, then where it happened</comment>
        <translation>%1（%2）</translation>
    </message>
</context>
<context>
    <name>ui::FitPanel</name>
    <message>
        <source>Order</source>
        <translation>阶数</translation>
    </message>
    <message>
        <source>auto (adjusted R²)</source>
        <translation>自动（调整后 R²）</translation>
    </message>
    <message>
        <source>The order chosen by adjusted R² with a significance margin, or the one you pick</source>
        <translation>按调整后 R² 并留有显著性裕量自动选定的阶数，或您手动选择的阶数</translation>
    </message>
    <message>
        <source>order</source>
        <translation>阶数</translation>
    </message>
    <message>
        <source>SSE (µm²)</source>
        <translation>残差平方和 (µm²)</translation>
    </message>
    <message>
        <source>R²</source>
        <translation>R²</translation>
    </message>
    <message>
        <source>adjusted R²</source>
        <translation>调整后 R²</translation>
    </message>
    <message>
        <source>Residuals of the chosen fit: mean deviation − curve (µm)</source>
        <translation>所选拟合的残差：平均偏差 − 曲线 (µm)</translation>
    </message>
    <message>
        <source>target (mm)</source>
        <translation>目标位置 (mm)</translation>
    </message>
    <message>
        <source>residual (µm)</source>
        <translation>残差 (µm)</translation>
    </message>
    <message>
        <source>Upload to instrument</source>
        <translation>上传到仪器</translation>
    </message>
    <message>
        <source>Enable</source>
        <translation>启用</translation>
    </message>
    <message>
        <source>Disable</source>
        <translation>停用</translation>
    </message>
    <message>
        <source>keep for power-up</source>
        <translation>上电保持</translation>
    </message>
    <message>
        <source>Also saves the compensation and this state in the instrument, so it powers up with it</source>
        <translation>同时将补偿及其启用状态保存在仪器中，使仪器上电后即带补偿运行</translation>
    </message>
    <message>
        <source>Run an axis test to fit its error curve.</source>
        <translation>运行单轴测试以拟合其误差曲线。</translation>
    </message>
    <message>
        <source>not enough points</source>
        <translation>点数不足</translation>
    </message>
    <message>
        <source>Order %1%2: e(x) = %3 µm (x in mm); backlash %4</source>
        <translation>%1 阶%2：e(x) = %3 µm（x 单位为 mm）；反向间隙 %4</translation>
    </message>
    <message>
        <source> (your choice)</source>
        <translation>（手动选择）</translation>
    </message>
    <message>
        <source> (adjusted R²)</source>
        <translation>（按调整后 R²）</translation>
    </message>
    <message>
        <source>No instrument.</source>
        <translation>没有仪器。</translation>
    </message>
    <message>
        <source>The instrument has no axis %1.</source>
        <translation>仪器没有 %1 轴。</translation>
    </message>
    <message>
        <source>Reading the instrument&apos;s compensation of %1…</source>
        <translation>正在读取仪器中 %1 轴的补偿…</translation>
    </message>
    <message>
        <source>The instrument holds no compensation for %1.</source>
        <translation>仪器中没有 %1 轴的补偿。</translation>
    </message>
    <message>
        <source>The instrument holds a compensation for %1: %2%3%4.</source>
        <translation>仪器中存有 %1 轴的补偿：%2%3%4。</translation>
    </message>
    <message>
        <source>enabled</source>
        <translation>已启用</translation>
    </message>
    <message>
        <source>disabled</source>
        <translation>已停用</translation>
    </message>
    <message>
        <source>, applied once the axis is homed</source>
        <translation>，回零后生效</translation>
    </message>
    <message>
        <source>, kept for power-up</source>
        <translation>，上电保持</translation>
    </message>
    <message>
        <source>Run an axis test first: the fit of its mean deviations is what is uploaded</source>
        <translation>请先运行单轴测试：上传的是其平均偏差的拟合结果</translation>
    </message>
    <message>
        <source>Sends the chosen fit to the instrument (installed disabled)</source>
        <translation>将所选拟合发送到仪器（安装后处于停用状态）</translation>
    </message>
    <message>
        <source>Upload a compensation first</source>
        <translation>请先上传补偿</translation>
    </message>
    <message>
        <source>The instrument compensates every target from now on</source>
        <translation>此后仪器对每个目标位置进行补偿</translation>
    </message>
    <message>
        <source>The instrument stops compensating (it keeps the compensation)</source>
        <translation>仪器停止补偿（补偿数据仍保留）</translation>
    </message>
    <message>
        <source>The instrument refused the compensation: %1</source>
        <translation>仪器拒绝了该补偿：%1</translation>
    </message>
    <message>
        <source>Compensation of %1 uploaded (disabled until you enable it).</source>
        <translation>%1 轴的补偿已上传（在您启用之前处于停用状态）。</translation>
    </message>
    <message>
        <source>The instrument refused: %1</source>
        <translation>仪器拒绝：%1</translation>
    </message>
</context>
<context>
    <name>ui::GainsPanel</name>
    <message>
        <source>Kp %1 · Ki %2 /s · Kd %3</source>
        <translation>Kp %1 · Ki %2 /s · Kd %3</translation>
    </message>
    <message>
        <source>continuous</source>
        <translation>连续形式</translation>
    </message>
    <message>
        <source>per control period</source>
        <translation>每控制周期</translation>
    </message>
    <message>
        <source>Kp</source>
        <translation>Kp</translation>
    </message>
    <message>
        <source>Ki [1/s]</source>
        <translation>Ki [1/s]</translation>
    </message>
    <message>
        <source>Kd [s]</source>
        <translation>Kd [s]</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>应用</translation>
    </message>
    <message>
        <source>Send these gains to the target; they take over between two control periods (bumpless)</source>
        <translation>将这些增益发送到对象；在两个控制周期之间接管（无扰切换）</translation>
    </message>
    <message>
        <source>Revert</source>
        <translation>恢复</translation>
    </message>
    <message>
        <source>Apply again the set that was in force before the last change</source>
        <translation>重新应用上次更改前生效的那组增益</translation>
    </message>
    <message>
        <source>Save to device</source>
        <translation>存入设备</translation>
    </message>
    <message>
        <source>Apply these gains and keep them as the device&apos;s power-up gains</source>
        <translation>应用这些增益，并保存为设备的上电增益</translation>
    </message>
    <message>
        <source>Read back</source>
        <translation>回读</translation>
    </message>
    <message>
        <source>Read the gains in force from the device</source>
        <translation>从设备读取当前生效的增益</translation>
    </message>
    <message>
        <source>edited</source>
        <translation>手动编辑</translation>
    </message>
    <message>
        <source>reverted to %1</source>
        <translation>恢复为 %1</translation>
    </message>
    <message>
        <source>Applied gain sets</source>
        <translation>已应用的增益组</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>时间</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>来源</translation>
    </message>
    <message>
        <source>no target chosen</source>
        <translation>未选择对象</translation>
    </message>
    <message>
        <source>PID gains</source>
        <translation>PID 增益</translation>
    </message>
    <message>
        <source>PID gains of %1</source>
        <translation>%1 的 PID 增益</translation>
    </message>
    <message>
        <source>the device</source>
        <translation>设备</translation>
    </message>
    <message>
        <source>the model&apos;s loop</source>
        <translation>模型的控制回路</translation>
    </message>
    <message>
        <source>kp = %1</source>
        <translation>kp = %1</translation>
    </message>
    <message>
        <source>ki = %1</source>
        <translation>ki = %1</translation>
    </message>
    <message>
        <source>kd = %1</source>
        <translation>kd = %1</translation>
    </message>
    <message>
        <source>Ti = Kp/Ki = %1 · Td = Kd/Kp = %2%3</source>
        <translation>Ti = Kp/Ki = %1 · Td = Kd/Kp = %2%3</translation>
    </message>
    <message>
        <source> · edited, not applied</source>
        <translation> · 已编辑，未应用</translation>
    </message>
    <message>
        <source>Shown in continuous form: Kp, Ki in 1/s, Kd in s. Beside them the discrete gains per control period T = %1 that %2 runs: ki = Ki·T, kd = Kd/T.</source>
        <translation>以连续形式显示：Kp，Ki 单位为 1/s，Kd 单位为 s。旁边是 %2 在控制周期 T = %1 下实际执行的离散增益：ki = Ki·T，kd = Kd/T。</translation>
    </message>
    <message>
        <source>Incremental PID: Δu = kp·(e_k − e_k−1) + ki·e_k + kd·(e_k − 2e_k−1 + e_k−2); see docs/tuning.md (the stage paper&apos;s eq. 2).</source>
        <translation>增量式 PID：Δu = kp·(e_k − e_k−1) + ki·e_k + kd·(e_k − 2e_k−1 + e_k−2)；见 docs/tuning.md（载物台文献的式 2）。</translation>
    </message>
    <message>
        <source>%1 Nothing is sent until it is fixed.</source>
        <translation>%1 改正之前不会发送任何值。</translation>
    </message>
    <message>
        <source>%1 is still being typed: nothing is sent until it is a number.</source>
        <translation>%1 尚未输入完：成为数字之前不会发送任何内容。</translation>
    </message>
    <message>
        <source>Put the gains in force back in the fields (nothing is sent)</source>
        <translation>把当前生效的增益放回输入框（不发送任何内容）</translation>
    </message>
</context>
<context>
    <name>ui::GridMapPanel</name>
    <message>
        <source>A grid map is running.</source>
        <translation>网格图正在运行。</translation>
    </message>
    <message>
        <source>Open a camera first, on the Scan or Jog screen&apos;s Camera tab, with the grid plate under it (on the simulator: the sim camera, with benchpilot started with --specimen grid-plate).</source>
        <translation>请先在扫描或点动界面的相机选项卡中打开相机，并将网格板置于其下（在模拟器上：使用 sim 相机，并以 --specimen grid-plate 启动 benchpilot）。</translation>
    </message>
    <message>
        <source>No instrument to map.</source>
        <translation>没有可测绘的仪器。</translation>
    </message>
    <message>
        <source>Grid map written to %1.</source>
        <translation>网格图已写入 %1。</translation>
    </message>
    <message>
        <source>Run a grid map first: the 2D table is fitted to it.</source>
        <translation>请先运行网格图：二维补偿表据此拟合。</translation>
    </message>
    <message>
        <source>This map&apos;s grid cannot be made into a 2D table the device keeps (2 to 41 nodes a side).</source>
        <translation>此网格图的网格无法生成设备可保存的二维补偿表（每边 2 到 41 个节点）。</translation>
    </message>
    <message>
        <source>The instrument went away.</source>
        <translation>仪器已断开。</translation>
    </message>
    <message>
        <source>The device did not enable the 2D table.</source>
        <translation>设备未启用二维补偿表。</translation>
    </message>
    <message>
        <source>2D table of %1 × %2 nodes uploaded and enabled: run the grid map again to see the after.</source>
        <translation>已上传并启用 %1 × %2 个节点的二维补偿表：再次运行网格图即可查看补偿后效果。</translation>
    </message>
    <message>
        <source>Uploading the 2D table…</source>
        <translation>正在上传二维补偿表…</translation>
    </message>
    <message>
        <source>2D table enabled.</source>
        <translation>二维补偿表已启用。</translation>
    </message>
    <message>
        <source>Ready.</source>
        <translation>就绪。</translation>
    </message>
    <message>
        <source>Mapping: %1 of %2 nodes</source>
        <translation>测绘中：第 %1 / %2 个节点</translation>
    </message>
    <message>
        <source>Stopped after %1 of %2 nodes.</source>
        <translation>在 %2 个节点中的第 %1 个之后停止。</translation>
    </message>
    <message>
        <source>Finished: %1 of %2 nodes without a reading.</source>
        <translation>已完成：%2 个节点中有 %1 个没有读数。</translation>
    </message>
    <message>
        <source>Finished: %1 nodes.</source>
        <translation>已完成：%1 个节点。</translation>
    </message>
    <message>
        <source>before</source>
        <translation>补偿前</translation>
    </message>
    <message>
        <source>after</source>
        <translation>补偿后</translation>
    </message>
    <message>
        <source>value</source>
        <translation>值</translation>
    </message>
    <message>
        <source>Run the grid map again (after)</source>
        <translation>再次运行网格图（补偿后）</translation>
    </message>
    <message>
        <source>Run grid map</source>
        <translation>运行网格图</translation>
    </message>
    <message>
        <source>Pitch</source>
        <translation>间距</translation>
    </message>
    <message>
        <source>Nodes</source>
        <translation>节点</translation>
    </message>
    <message>
        <source>Abort</source>
        <translation>中止</translation>
    </message>
    <message>
        <source>Fit, upload and enable the 2D table</source>
        <translation>拟合、上传并启用二维补偿表</translation>
    </message>
    <message>
        <source>Disable the 2D table</source>
        <translation>停用二维补偿表</translation>
    </message>
    <message>
        <source>What the camera cannot know by itself: a pixel size calibrated by moving this same stage carries the stage&apos;s scale error into the image. The scales are those of the plate&apos;s certified pitch.</source>
        <translation>相机自身无法知道的：用同一平台移动标定的像素尺寸会把平台的比例误差带入图像。比例误差以网格板的认证间距为准。</translation>
    </message>
    <message>
        <source>scale X (ppm)</source>
        <translation>X 比例误差 (ppm)</translation>
    </message>
    <message>
        <source>scale Y (ppm)</source>
        <translation>Y 比例误差 (ppm)</translation>
    </message>
    <message>
        <source>squareness (µrad)</source>
        <translation>垂直度 (µrad)</translation>
    </message>
    <message>
        <source>straightness X (µm)</source>
        <translation>X 直线度 (µm)</translation>
    </message>
    <message>
        <source>straightness Y (µm)</source>
        <translation>Y 直线度 (µm)</translation>
    </message>
    <message>
        <source>error RMS (µm)</source>
        <translation>误差均方根 (µm)</translation>
    </message>
    <message>
        <source>error max (µm)</source>
        <translation>最大误差 (µm)</translation>
    </message>
    <message>
        <source>residual RMS (µm)</source>
        <translation>残差均方根 (µm)</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Distance between the nodes visited, a whole multiple of the plate&apos;s dot pitch</source>
        <translation>所访问节点之间的距离，须为网格板点距的整数倍</translation>
    </message>
    <message>
        <source>Columns</source>
        <translation>列数</translation>
    </message>
    <message>
        <source>Rows</source>
        <translation>行数</translation>
    </message>
    <message>
        <source>Both directions</source>
        <translation>双向</translation>
    </message>
    <message>
        <source>Read every node twice: approached from −X −Y, then again in reverse order from +X +Y. The map is the mean of the two; each node gets its reversal (forward − reverse), whose mean along X and Y is the lost motion a 2D table cannot correct.</source>
        <translation>每个节点读取两次：先从 −X −Y 方向趋近，再按相反顺序从 +X +Y 方向趋近。网格图取两者的平均值；每个节点得到其反向差（正向 − 反向），其沿 X 和 Y 的平均值即二维补偿表无法校正的空程。</translation>
    </message>
    <message>
        <source>Arrows</source>
        <translation>箭头</translation>
    </message>
    <message>
        <source>errors</source>
        <translation>误差</translation>
    </message>
    <message>
        <source>reversals</source>
        <translation>反向差</translation>
    </message>
    <message>
        <source>What the map&apos;s arrows and colours show: each node&apos;s error, or its reversal (forward − reverse)</source>
        <translation>网格图的箭头和颜色显示的内容：每个节点的误差，或其反向差（正向 − 反向）</translation>
    </message>
    <message>
        <source>Mapping both ways: %1 of %2 readings</source>
        <translation>双向测绘：%2 次读数中的第 %1 次</translation>
    </message>
    <message>
        <source>reversal max (µm)</source>
        <translation>反向差最大值 (µm)</translation>
    </message>
    <message>
        <source>mean reversal X (µm)</source>
        <translation>X 平均反向差 (µm)</translation>
    </message>
    <message>
        <source>mean reversal Y (µm)</source>
        <translation>Y 平均反向差 (µm)</translation>
    </message>
    <message>
        <source>Stopped after %1 of %2 readings (each node both ways).</source>
        <translation>已完成 %2 次读数中的 %1 次后停止（每个节点双向各读一次）。</translation>
    </message>
    <message>
        <source>Finished: %1 of %2 readings (each node both ways) failed.</source>
        <translation>完成：%2 次读数（每个节点双向各读一次）中有 %1 次失败。</translation>
    </message>
    <message>
        <source>Finished: %1 nodes, each read both ways.</source>
        <translation>完成：%1 个节点，每个节点双向各读一次。</translation>
    </message>
    <message>
        <source>The after map reads the before map&apos;s grid: pitch %1 mm, %2 × %3 nodes. Set those, or disable the 2D table to start a new before map.</source>
        <translation>补偿后的网格图沿用补偿前网格图的网格：节距 %1 mm，%2 × %3 个节点。请改回这些设置，或禁用二维补偿表以重新测量补偿前的网格图。</translation>
    </message>
</context>
<context>
    <name>ui::GridMapView</name>
    <message>
        <source>No map yet: put the grid plate under the camera, a dot near the image centre, and run a grid map.</source>
        <translation>尚无网格图：将网格板置于相机下，使一个圆点靠近图像中心，然后运行网格图。</translation>
    </message>
    <message>
        <source>After: 2D table on</source>
        <translation>补偿后：二维补偿表已启用</translation>
    </message>
    <message>
        <source>Before: compensation off</source>
        <translation>补偿前：补偿关闭</translation>
    </message>
    <message>
        <source>RMS %1 µm</source>
        <translation>均方根 %1 µm</translation>
    </message>
    <message>
        <source>arrows magnified %1×; colour: the error&apos;s length</source>
        <translation>箭头放大 %1 倍；颜色：误差长度</translation>
    </message>
    <message>
        <source>mean reversal X %1 µm, Y %2 µm</source>
        <translation>平均反向差 X %1 µm，Y %2 µm</translation>
    </message>
    <message>
        <source>read one way: no reversal</source>
        <translation>单向读取：无反向差</translation>
    </message>
    <message>
        <source>RMS %1 µm, mean of both directions</source>
        <translation>均方根 %1 µm，两个方向的平均值</translation>
    </message>
    <message>
        <source>reversals (forward − reverse) magnified %1×; colour: their length</source>
        <translation>反向差（正向 − 反向）放大 %1 倍；颜色：其长度</translation>
    </message>
</context>
<context>
    <name>ui::JogPad</name>
    <message>
        <source>▲ back</source>
        <translation>▲ 后</translation>
    </message>
    <message>
        <source>Y toward the back</source>
        <translation>Y 向后</translation>
    </message>
    <message>
        <source>◀ X−</source>
        <translation>◀ X−</translation>
    </message>
    <message>
        <source>X to the left</source>
        <translation>X 向左</translation>
    </message>
    <message>
        <source>X+ ▶</source>
        <translation>X+ ▶</translation>
    </message>
    <message>
        <source>X to the right</source>
        <translation>X 向右</translation>
    </message>
    <message>
        <source>▼ front</source>
        <translation>▼ 前</translation>
    </message>
    <message>
        <source>Y toward the front</source>
        <translation>Y 向前</translation>
    </message>
    <message>
        <source>Z up</source>
        <translation>Z 上</translation>
    </message>
    <message>
        <source>Raise the tip</source>
        <translation>抬起加样针</translation>
    </message>
    <message>
        <source>Z down</source>
        <translation>Z 下</translation>
    </message>
    <message>
        <source>Lower the tip</source>
        <translation>降下加样针</translation>
    </message>
    <message>
        <source>hold to move</source>
        <translation>按住移动</translation>
    </message>
    <message>
        <source>step %1 mm</source>
        <translation>步长 %1 mm</translation>
    </message>
    <message>
        <source>Hold a button to move while it is pressed, or choose a step for each click</source>
        <translation>按住按钮持续移动，或选择每次点击的步长</translation>
    </message>
    <message>
        <source>Speed as a share of each axis&apos; maximum (slow for teaching)</source>
        <translation>速度占各轴最大速度的比例（示教时用慢速）</translation>
    </message>
    <message>
        <source>speed</source>
        <translation>速度</translation>
    </message>
</context>
<context>
    <name>ui::JogScreen</name>
    <message>
        <source>Home all</source>
        <translation>全部回零</translation>
    </message>
    <message>
        <source>Home every axis (the analyzer lifts Z first, then X and Y)</source>
        <translation>所有轴回零（分析仪先抬起 Z，再回 X 和 Y）</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>Decelerate every axis to rest (Space)</source>
        <translation>所有轴减速至停止（空格键）</translation>
    </message>
    <message>
        <source>Jog speed</source>
        <translation>点动速度</translation>
    </message>
    <message>
        <source>Hold-to-jog speed as a share of each axis&apos; maximum; hold Shift for full speed</source>
        <translation>按住点动的速度占各轴最大速度的比例；按住 Shift 为全速</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>No instrument</source>
        <translation>无仪器</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>轴</translation>
    </message>
    <message>
        <source>Commanded</source>
        <translation>指令位置</translation>
    </message>
    <message>
        <source>Grating</source>
        <translation>光栅尺</translation>
    </message>
    <message>
        <source>Encoder</source>
        <translation>编码器</translation>
    </message>
    <message>
        <source>Homed</source>
        <translation>已回零</translation>
    </message>
    <message>
        <source>Home sw</source>
        <translation>零位开关</translation>
    </message>
    <message>
        <source>Limit sw</source>
        <translation>限位开关</translation>
    </message>
    <message>
        <source>Moving</source>
        <translation>运动中</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>步进</translation>
    </message>
    <message>
        <source>Hold</source>
        <translation>按住</translation>
    </message>
    <message>
        <source>Go to</source>
        <translation>移到</translation>
    </message>
    <message>
        <source>Soft limits</source>
        <translation>软限位</translation>
    </message>
    <message>
        <source> Z rises to its switch first, then the other axes go to theirs.</source>
        <translation> Z 先升到其开关，其他轴再回到各自的开关。</translation>
    </message>
    <message>
        <source>Move %1 from %2 to %3 %4? That is %5 %4.</source>
        <translation>把 %1 从 %2 移到 %3 %4？移动距离 %5 %4。</translation>
    </message>
    <message>
        <source>Set home here…</source>
        <translation>设此处为原点…</translation>
    </message>
    <message>
        <source>Take the present position as home for every axis (the controller cannot home): absolute moves count from here</source>
        <translation>将当前位置设为各轴原点（控制器无法回零）：绝对移动从此处起算</translation>
    </message>
    <message>
        <source>Unlock…</source>
        <translation>解锁…</translation>
    </message>
    <message>
        <source>The controller lost track of its position: take the position it believes as true (or home it)</source>
        <translation>控制器已丢失位置：采用其认定的位置（或回零）</translation>
    </message>
    <message>
        <source>Take the present position as home for every axis of the %1? Absolute moves then count from here: do so only when you know where the machine stands.</source>
        <translation>将当前位置设为%1各轴的原点？此后绝对移动从此处起算：仅在确知设备所处位置时这样做。</translation>
    </message>
    <message>
        <source>Unlock the %1? Its controller lost track of its position; unlocking takes the position it believes as true. Home it as soon as you can.</source>
        <translation>解锁%1？其控制器已丢失位置；解锁即采用其认定的位置为准。请尽快回零。</translation>
    </message>
    <message>
        <source>E-STOP active — press Reset E-stop to clear</source>
        <translation>急停已触发 — 按“急停复位”解除</translation>
    </message>
    <message>
        <source>Connect the instrument first</source>
        <translation>请先连接仪器</translation>
    </message>
    <message>
        <source>E-STOP is latched: press Reset E-stop first</source>
        <translation>急停已锁定：请先按“急停复位”</translation>
    </message>
    <message>
        <source>A list has the keys — click an empty spot to jog with them</source>
        <translation>列表正在使用按键 — 点击空白处即可用按键点动</translation>
    </message>
    <message>
        <source>Typing in a field — press Enter or click an empty spot to jog with the keys</source>
        <translation>正在输入框中输入 — 按回车或点击空白处即可用按键点动</translation>
    </message>
    <message>
        <source>Keys jog the axes</source>
        <translation>按键点动各轴</translation>
    </message>
    <message>
        <source> The plunger holds %1 µL: homing it pushes that out of the tip, wherever the tip is now.</source>
        <translation>柱塞中有 %1 µL：回零会把它从加样针推出，无论加样针此刻在哪里。</translation>
    </message>
    <message>
        <source>Home %1 of the %2?%3%4 Keep hands and labware clear.</source>
        <translation>让%2的 %1 回零？%3%4请让手和器皿远离。</translation>
    </message>
    <message>
        <source>Keys: Space stop, Esc E-stop</source>
        <translation>按键：空格停止，Esc 急停</translation>
    </message>
    <message>
        <source>Keys: %1, Shift fast, Space stop, Esc E-stop</source>
        <translation>按键：%1，Shift 快速，空格停止，Esc 急停</translation>
    </message>
    <message>
        <source>, </source>
        <comment>between the items of a list</comment>
        <translation>，</translation>
    </message>
</context>
<context>
    <name>ui::JoystickPad</name>
    <message>
        <source>Drag the knob: speed grows with the distance from the centre. Let go to stop.</source>
        <translation>拖动旋钮：速度随离中心的距离增大。松开即停。</translation>
    </message>
    <message>
        <source>+X</source>
        <comment>joystick direction</comment>
        <translation>+X</translation>
    </message>
    <message>
        <source>+Y</source>
        <comment>joystick direction</comment>
        <translation>+Y</translation>
    </message>
</context>
<context>
    <name>ui::JoystickScreen</name>
    <message>
        <source>Z: push up or down; it springs back to the centre (stop) when let go</source>
        <translation>Z：向上或向下推；松开后弹回中心（停止）</translation>
    </message>
    <message>
        <source>Z</source>
        <translation>Z</translation>
    </message>
    <message>
        <source>Response</source>
        <translation>响应</translation>
    </message>
    <message>
        <source> mm/s</source>
        <translation> mm/s</translation>
    </message>
    <message>
        <source>Speed at full deflection (each axis is also held to its own maximum)</source>
        <translation>满偏转时的速度（各轴也受自身最大值限制）</translation>
    </message>
    <message>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <source>Deflection around the centre that does nothing</source>
        <translation>中心附近不起作用的偏转范围</translation>
    </message>
    <message>
        <source>0: speed grows linearly with deflection; 1: cubically (finer near the centre)</source>
        <translation>0：速度随偏转线性增大；1：按三次方增大（中心附近更精细）</translation>
    </message>
    <message>
        <source>Max speed</source>
        <translation>最大速度</translation>
    </message>
    <message>
        <source>Dead-band</source>
        <translation>死区</translation>
    </message>
    <message>
        <source>Expo</source>
        <translation>指数</translation>
    </message>
    <message>
        <source>Drag the knob; let go to stop. Arrow keys push the stick to the rim, PgUp/PgDn move Z. Esc: E-stop.</source>
        <translation>拖动旋钮，松开即停。方向键把摇杆推到边缘，PgUp/PgDn 移动 Z。Esc：急停。</translation>
    </message>
    <message>
        <source>Clear trail</source>
        <translation>清除轨迹</translation>
    </message>
    <message>
        <source>No instrument</source>
        <translation>无仪器</translation>
    </message>
    <message>
        <source>%1 — joystick</source>
        <translation>%1 — 摇杆</translation>
    </message>
    <message>
        <source>&lt;tr&gt;&lt;td&gt;&lt;b&gt;%1&lt;/b&gt;&lt;/td&gt;&lt;td align=right&gt;%2&lt;/td&gt;&lt;td align=right&gt;%3&lt;/td&gt;&lt;td&gt;%4&lt;/td&gt;&lt;/tr&gt;</source>
        <translation>&lt;tr&gt;&lt;td&gt;&lt;b&gt;%1&lt;/b&gt;&lt;/td&gt;&lt;td align=right&gt;%2&lt;/td&gt;&lt;td align=right&gt;%3&lt;/td&gt;&lt;td&gt;%4&lt;/td&gt;&lt;/tr&gt;</translation>
    </message>
    <message>
        <source>not homed</source>
        <translation>未回零</translation>
    </message>
    <message>
        <source>&lt;table cellspacing=6&gt;&lt;tr&gt;&lt;td&gt;&lt;/td&gt;&lt;td&gt;commanded&lt;/td&gt;&lt;td&gt;%1&lt;/td&gt;&lt;td&gt;&lt;/td&gt;&lt;/tr&gt;%2&lt;/table&gt;</source>
        <translation>&lt;table cellspacing=6&gt;&lt;tr&gt;&lt;td&gt;&lt;/td&gt;&lt;td&gt;指令&lt;/td&gt;&lt;td&gt;%1&lt;/td&gt;&lt;td&gt;&lt;/td&gt;&lt;/tr&gt;%2&lt;/table&gt;</translation>
    </message>
    <message>
        <source>grating</source>
        <translation>光栅尺</translation>
    </message>
    <message>
        <source>encoder</source>
        <translation>编码器</translation>
    </message>
    <message>
        <source>Commanded speed: %1 mm/s</source>
        <translation>指令速度：%1 mm/s</translation>
    </message>
    <message>
        <source>E-STOP active — press Reset E-stop to clear</source>
        <translation>急停已触发 — 按“急停复位”解除</translation>
    </message>
    <message>
        <source> · %1 held at its soft limit</source>
        <translation> · %1 停在软限位</translation>
    </message>
    <message>
        <source>The last positions read before the link went down, not where the axes are now</source>
        <translation>链路断开前最后读到的位置，并非各轴现在的位置</translation>
    </message>
    <message>
        <source>Drag the knob; let go to stop. Arrow keys push the stick to the rim. Esc: E-stop.</source>
        <translation>拖动旋钮，松开即停。方向键把摇杆推到边缘。Esc：急停。</translation>
    </message>
</context>
<context>
    <name>ui::LiveStrip</name>
    <message>
        <source>Live: position and following error of axis</source>
        <translation>实时：该轴的位置与跟随误差</translation>
    </message>
    <message>
        <source>The axis plotted below; jogging an axis also chooses it</source>
        <translation>下方绘制的轴；点动某轴也会选中它</translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>时间 (s)</translation>
    </message>
    <message>
        <source>Plots screen paused: this strip stops once that pause has filled its window</source>
        <translation>曲线界面已暂停：暂停填满其窗口后本条也会停止</translation>
    </message>
</context>
<context>
    <name>ui::LiveView</name>
    <message>
        <source>No picture: open a camera.</source>
        <translation>无图像：请打开相机。</translation>
    </message>
    <message>
        <source>%1 µm</source>
        <translation>%1 µm</translation>
    </message>
    <message>
        <source>Pixel size not known: no scale bar</source>
        <translation>像元尺寸未知：无比例尺</translation>
    </message>
    <message>
        <source>X %1  Y %2 mm</source>
        <translation>X %1  Y %2 mm</translation>
    </message>
    <message>
        <source>Stage position not known</source>
        <translation>载物台位置未知</translation>
    </message>
    <message>
        <source>%1 × %2 px · %3-bit · frame %4</source>
        <translation>%1 × %2 px · %3 位 · 第 %4 帧</translation>
    </message>
    <message>
        <source>Focus: —</source>
        <translation>对焦：—</translation>
    </message>
    <message>
        <source>Focus: %1</source>
        <translation>对焦：%1</translation>
    </message>
    <message>
        <source>Variance of the Laplacian (× 10⁴) of a downscaled copy: higher is sharper. Turn the focus until it peaks.</source>
        <translation>缩小副本的拉普拉斯方差（× 10⁴）：越高越清晰。调焦直到它达到峰值。</translation>
    </message>
    <message>
        <source>Levels %1–%2 of %3</source>
        <translation>灰度 %1–%2（共 %3）</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>继续</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <source>Hold the picture still, or take frames again</source>
        <translation>定住画面，或重新接收帧</translation>
    </message>
    <message>
        <source>Auto contrast</source>
        <translation>自动对比度</translation>
    </message>
    <message>
        <source>Stretch the levels so the darkest and brightest 0.1 % of the pixels clip; off, the full bit depth maps black to white</source>
        <translation>拉伸灰度，使最暗和最亮的 0.1% 像素截断；关闭时，整个位深从黑映射到白</translation>
    </message>
</context>
<context>
    <name>ui::MessageBanner</name>
    <message>
        <source>Dismiss</source>
        <translation>关闭</translation>
    </message>
    <message>
        <source>%1 (×%2)</source>
        <translation>%1（×%2）</translation>
    </message>
    <message>
        <source>+%1 more</source>
        <translation>还有 %1 条</translation>
    </message>
    <message>
        <source>Dismiss: show the next message</source>
        <translation>关闭：显示下一条消息</translation>
    </message>
</context>
<context>
    <name>ui::MosaicCanvas</name>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <source>%1 µm</source>
        <translation>%1 µm</translation>
    </message>
    <message>
        <source>The mosaic shows here after a stitch: zoom with the wheel, drag to pan, double-click to move the stage there.</source>
        <translation>拼接完成后拼接图显示在这里：用滚轮缩放，拖动平移，双击将载物台移到该处。</translation>
    </message>
</context>
<context>
    <name>ui::MosaicFolder</name>
    <message>
        <source>%1 holds no stitched mosaic (no .stitch.json report): stitch it first.</source>
        <translation>%1 中没有拼接好的拼接图（没有 .stitch.json 报告）：请先拼接。</translation>
    </message>
    <message>
        <source>%1 cannot be read: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <source>%1, line %2, column %3: %4</source>
        <translation>%1，第 %2 行，第 %3 列：%4</translation>
    </message>
    <message>
        <source>%1 is not a stitch report BenchPilot can show: %2</source>
        <translation>%1 不是 BenchPilot 能显示的拼接报告：%2</translation>
    </message>
    <message>
        <source>it names no mosaic file in the folder</source>
        <translation>报告未指明文件夹中的拼接图文件</translation>
    </message>
    <message>
        <source>its mosaic does not say where its top-left pixel was on the stage</source>
        <translation>其拼接图未记录左上角像素在载物台上的位置</translation>
    </message>
    <message>
        <source>it lists no tiles</source>
        <translation>报告中没有图块</translation>
    </message>
    <message>
        <source>tile %1 has no file, stage_px or registered_px</source>
        <translation>图块 %1 缺少 file、stage_px 或 registered_px</translation>
    </message>
    <message>
        <source>The tile size comes from the tiles: %1</source>
        <translation>图块尺寸取自图块文件：%1</translation>
    </message>
</context>
<context>
    <name>ui::MosaicViewer</name>
    <message>
        <source>The mosaic %1 cannot be shown: %2</source>
        <translation>无法显示拼接图 %1：%2</translation>
    </message>
    <message>
        <source>(%1, %2) mm</source>
        <translation>(%1, %2) mm</translation>
    </message>
    <message>
        <source>The stage is not connected: it cannot go to %1.</source>
        <translation>载物台未连接：无法移到 %1。</translation>
    </message>
    <message>
        <source>Home the stage first: going to %1 in the mosaic is a move to an absolute position.</source>
        <translation>请先将载物台回零：移到拼接图中的 %1 是一次绝对位置移动。</translation>
    </message>
    <message>
        <source>A scan is running: the stage goes to %1 once it has finished.</source>
        <translation>扫描正在运行：扫描结束后载物台才能移到 %1。</translation>
    </message>
    <message>
        <source>%1 is outside the stage&apos;s soft limits (X %2 to %3 mm, Y %4 to %5 mm): the stage stays where it is.</source>
        <translation>%1 超出载物台的软限位（X %2 至 %3 mm，Y %4 至 %5 mm）：载物台保持不动。</translation>
    </message>
    <message>
        <source>Move the stage to %1? That is %2 mm from where it is, farther than one camera field (%3 mm).</source>
        <translation>将载物台移到 %1？距当前位置 %2 mm，超过一个相机视场（%3 mm）。</translation>
    </message>
    <message>
        <source>The stage goes to %1, the point double-clicked in the mosaic.</source>
        <translation>载物台正移到 %1，即在拼接图中双击的点。</translation>
    </message>
    <message>
        <source>X %1  Y %2 mm under the cursor</source>
        <translation>光标处 X %1  Y %2 mm</translation>
    </message>
    <message>
        <source>zoom %1 %, pyramid level %2 (1:%3)</source>
        <translation>缩放 %1 %，金字塔层级 %2（1:%3）</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>适应窗口</translation>
    </message>
    <message>
        <source>Show the whole mosaic (F)</source>
        <translation>显示整幅拼接图（F）</translation>
    </message>
    <message>
        <source>+</source>
        <translation>+</translation>
    </message>
    <message>
        <source>Zoom in (+; or the mouse wheel, about the cursor)</source>
        <translation>放大（+；或用鼠标滚轮，以光标为中心）</translation>
    </message>
    <message>
        <source>−</source>
        <translation>−</translation>
    </message>
    <message>
        <source>Zoom out (−)</source>
        <translation>缩小（−）</translation>
    </message>
    <message>
        <source>Tiles</source>
        <translation>图块</translation>
    </message>
    <message>
        <source>Show each tile&apos;s outline where registration put it (T)</source>
        <translation>按配准后的位置显示每个图块的轮廓（T）</translation>
    </message>
    <message>
        <source>Quality</source>
        <translation>质量</translation>
    </message>
    <message>
        <source>Show each tile&apos;s correction from its stage position as an arrow, and the tiles placed by the stage hatched (Q)</source>
        <translation>以箭头显示每个图块相对其载物台位置的修正，并以斜线标出按载物台位置放置的图块（Q）</translation>
    </message>
    <message>
        <source>Drag or use the arrow keys to pan; double-click to move the stage to that point</source>
        <translation>拖动或用方向键平移；双击将载物台移到该点</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>打开</translation>
    </message>
    <message>
        <source>Show the mosaic stitched earlier in the output folder: its .stitch.json report and the mosaic it names (O)</source>
        <translation>显示输出文件夹中先前拼接的拼接图：其 .stitch.json 报告及报告所指的拼接图（O）</translation>
    </message>
</context>
<context>
    <name>ui::NumberField</name>
    <message>
        <source>the value</source>
        <translation>该值</translation>
    </message>
    <message>
        <source>%1 is empty: type a number</source>
        <translation>%1 为空：请输入数字</translation>
    </message>
    <message>
        <source>“%1” is not a number</source>
        <translation>“%1”不是数字</translation>
    </message>
    <message>
        <source>%1 must be a whole number</source>
        <translation>%1 必须是整数</translation>
    </message>
    <message>
        <source>%1 must be 0 or more, not %2</source>
        <translation>%1 必须不小于 0，而不是 %2</translation>
    </message>
    <message>
        <source>%1 must be at least %2, not %3</source>
        <translation>%1 必须不小于 %2，而不是 %3</translation>
    </message>
    <message>
        <source>%1 must be at most %2, not %3</source>
        <translation>%1 必须不大于 %2，而不是 %3</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
</context>
<context>
    <name>ui::PatternForm</name>
    <message>
        <source>Line</source>
        <translation>直线</translation>
    </message>
    <message>
        <source>Rectangle</source>
        <translation>矩形</translation>
    </message>
    <message>
        <source>Circle</source>
        <translation>圆</translation>
    </message>
    <message>
        <source>Arc</source>
        <translation>圆弧</translation>
    </message>
    <message>
        <source>Sine (chords)</source>
        <translation>正弦（弦线逼近）</translation>
    </message>
    <message>
        <source>Cosine (chords)</source>
        <translation>余弦（弦线逼近）</translation>
    </message>
    <message>
        <source>Spiral</source>
        <translation>螺旋线</translation>
    </message>
    <message>
        <source>Raster (serpentine)</source>
        <translation>栅格扫描（蛇形）</translation>
    </message>
    <message>
        <source>a name for the saved file</source>
        <translation>保存文件所用的名称</translation>
    </message>
    <message>
        <source> mm/s</source>
        <translation> mm/s</translation>
    </message>
    <message>
        <source>Path speed (feed): how fast the pattern is run along its length</source>
        <translation>路径速度（进给速度）：沿图形长度运行的快慢</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>名称</translation>
    </message>
    <message>
        <source>Shape</source>
        <translation>形状</translation>
    </message>
    <message>
        <source>Feed</source>
        <translation>进给速度</translation>
    </message>
    <message>
        <source>work at Z</source>
        <translation>在指定 Z 高度工作</translation>
    </message>
    <message>
        <source>Z goes to this height once X and Y are at the start (seed 000: Z follows XY)</source>
        <translation>X 和 Y 到达起点后，Z 移到此高度（文献 000：Z 跟随 XY）</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Z</source>
        <translation>Z</translation>
    </message>
    <message>
        <source>X</source>
        <comment>axis</comment>
        <translation>X</translation>
    </message>
    <message>
        <source>Y</source>
        <comment>axis</comment>
        <translation>Y</translation>
    </message>
    <message>
        <source> °</source>
        <translation> °</translation>
    </message>
    <message>
        <source>counter-clockwise</source>
        <translation>逆时针</translation>
    </message>
    <message>
        <source>clockwise</source>
        <translation>顺时针</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>起点</translation>
    </message>
    <message>
        <source>Where the line begins</source>
        <translation>直线的起始位置</translation>
    </message>
    <message>
        <source>End</source>
        <translation>终点</translation>
    </message>
    <message>
        <source>Where the line ends</source>
        <translation>直线的结束位置</translation>
    </message>
    <message>
        <source>Corner</source>
        <translation>角点</translation>
    </message>
    <message>
        <source>Lower-left corner: the run starts and ends here</source>
        <translation>左下角：从此处开始，也在此处结束</translation>
    </message>
    <message>
        <source>Width</source>
        <translation>宽度</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>高度</translation>
    </message>
    <message>
        <source>Direction</source>
        <translation>方向</translation>
    </message>
    <message>
        <source>Centre</source>
        <translation>圆心</translation>
    </message>
    <message>
        <source>Radius</source>
        <translation>半径</translation>
    </message>
    <message>
        <source>Start angle</source>
        <translation>起始角</translation>
    </message>
    <message>
        <source>0° is +X, 90° is +Y</source>
        <translation>0° 为 +X，90° 为 +Y</translation>
    </message>
    <message>
        <source>Sweep</source>
        <translation>扫过角度</translation>
    </message>
    <message>
        <source>Origin</source>
        <translation>原点</translation>
    </message>
    <message>
        <source>Start of the wave&apos;s axis</source>
        <translation>波形轴线的起点</translation>
    </message>
    <message>
        <source>Amplitude</source>
        <translation>振幅</translation>
    </message>
    <message>
        <source>Wavelength</source>
        <translation>波长</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>长度</translation>
    </message>
    <message>
        <source>Along the wave&apos;s axis</source>
        <translation>沿波形轴线</translation>
    </message>
    <message>
        <source>Axis angle</source>
        <translation>轴线角度</translation>
    </message>
    <message>
        <source>Direction of the wave&apos;s axis, 0° = +X</source>
        <translation>波形轴线的方向，0° = +X</translation>
    </message>
    <message>
        <source>Chord tolerance</source>
        <translation>弦线容差</translation>
    </message>
    <message>
        <source>Largest gap between a chord and the curve (seed 002&apos;s equal parts)</source>
        <translation>弦线与曲线之间的最大间隙（文献 002 的等分法）</translation>
    </message>
    <message>
        <source>Start radius</source>
        <translation>起始半径</translation>
    </message>
    <message>
        <source>Pitch</source>
        <translation>螺距</translation>
    </message>
    <message>
        <source>Radius gained per turn</source>
        <translation>每圈增加的半径</translation>
    </message>
    <message>
        <source>Turns</source>
        <translation>圈数</translation>
    </message>
    <message>
        <source>Whole or half turns</source>
        <translation>整圈或半圈</translation>
    </message>
    <message>
        <source>Lower-left corner: the first pass starts here</source>
        <translation>左下角：第一道扫描从此处开始</translation>
    </message>
    <message>
        <source>Pass spacing</source>
        <translation>扫描道间距</translation>
    </message>
    <message>
        <source>along X</source>
        <translation>沿 X</translation>
    </message>
    <message>
        <source>along Y</source>
        <translation>沿 Y</translation>
    </message>
    <message>
        <source>Passes</source>
        <translation>扫描道数</translation>
    </message>
</context>
<context>
    <name>ui::PatternPreview</name>
    <message>
        <source>pattern</source>
        <translation>图形</translation>
    </message>
    <message>
        <source>point-by-point steps</source>
        <translation>逐点步进</translation>
    </message>
    <message>
        <source>commanded</source>
        <translation>指令</translation>
    </message>
    <message>
        <source>start</source>
        <translation>起点</translation>
    </message>
    <message>
        <source>measured (samples)</source>
        <translation>实测（采样点）</translation>
    </message>
    <message>
        <source>machine</source>
        <translation>机器位置</translation>
    </message>
    <message>
        <source>X (mm)</source>
        <translation>X (mm)</translation>
    </message>
    <message>
        <source>Y (mm)</source>
        <translation>Y (mm)</translation>
    </message>
</context>
<context>
    <name>ui::PatternScreen</name>
    <message>
        <source>Instrument</source>
        <translation>仪器</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>运行</translation>
    </message>
    <message>
        <source>Move to the pattern&apos;s start, then run it (F5)</source>
        <translation>移动到图形起点，然后运行（F5）</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <source>Slow down along the path and hold; press again to go on (F6)</source>
        <translation>沿路径减速并保持；再按一次继续（F6）</translation>
    </message>
    <message>
        <source>Abort</source>
        <translation>中止</translation>
    </message>
    <message>
        <source>Slow down along the path and give the rest up (F8)</source>
        <translation>沿路径减速并放弃剩余部分（F8）</translation>
    </message>
    <message>
        <source>%v / %m segments</source>
        <translation>%v / %m 段</translation>
    </message>
    <message>
        <source>Load…</source>
        <translation>载入…</translation>
    </message>
    <message>
        <source>Save…</source>
        <translation>保存…</translation>
    </message>
    <message>
        <source>Export run…</source>
        <translation>导出运行数据…</translation>
    </message>
    <message>
        <source>The last run&apos;s samples as CSV: commanded and measured XY, path distance, contour error</source>
        <translation>上次运行的采样数据，CSV 格式：指令与实测 XY、路径距离、轮廓误差</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>全图</translation>
    </message>
    <message>
        <source>Show the whole pattern (wheel: zoom, drag: pan)</source>
        <translation>显示整个图形（滚轮：缩放，拖动：平移）</translation>
    </message>
    <message>
        <source>Interpolation step</source>
        <translation>插补步距</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Grid of the point-by-point walk drawn when zoomed in (the instrument&apos;s resolution by default)</source>
        <translation>放大时绘制的逐点插补网格（默认为仪器的分辨率）</translation>
    </message>
    <message>
        <source>zoom in to see the steps</source>
        <translation>放大以查看步进</translation>
    </message>
    <message>
        <source>Load pattern</source>
        <translation>载入图形</translation>
    </message>
    <message>
        <source>Patterns (*.pattern.json)</source>
        <translation>图形 (*.pattern.json)</translation>
    </message>
    <message>
        <source>Save pattern</source>
        <translation>保存图形</translation>
    </message>
    <message>
        <source>Export run</source>
        <translation>导出运行数据</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <source>&lt;b&gt;Contour error&lt;/b&gt; max %1 µm (at %2 mm), RMS %3 µm · &lt;b&gt;time&lt;/b&gt; %4 · %5 samples at %6 Hz%7</source>
        <translation>&lt;b&gt;轮廓误差&lt;/b&gt; 最大 %1 µm（位于 %2 mm），均方根 %3 µm · &lt;b&gt;用时&lt;/b&gt; %4 · %5 个采样点，采样率 %6 Hz%7</translation>
    </message>
    <message>
        <source> · &lt;b&gt;incomplete&lt;/b&gt;</source>
        <translation> · &lt;b&gt;不完整&lt;/b&gt;</translation>
    </message>
    <message>
        <source>The pattern has problems (see above).</source>
        <translation>该图形有问题（见上方）。</translation>
    </message>
    <message>
        <source>%1 segments, %2 mm; estimated %3 at %4 mm/s</source>
        <translation>%1 段，%2 mm；以 %4 mm/s 预计用时 %3</translation>
    </message>
    <message>
        <source>Leaves the soft limits: %1</source>
        <translation>超出软限位：%1</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>继续</translation>
    </message>
    <message>
        <source>Move %1 %2 mm to the pattern&apos;s start (%3, %4) and run %5 segments (%6 mm)?</source>
        <translation>将%1移动 %2 mm 到图形起点（%3, %4），然后运行 %5 段（%6 mm）？</translation>
    </message>
    <message>
        <source>Moving to the start…</source>
        <translation>正在移向起点…</translation>
    </message>
    <message>
        <source>Running: segment %1 of %2, %3 mm done, about %4 left</source>
        <translation>运行中：第 %1 段（共 %2 段），已完成 %3 mm，约剩 %4</translation>
    </message>
    <message>
        <source>There is no run to export yet.</source>
        <translation>还没有可导出的运行数据。</translation>
    </message>
    <message>
        <source>A pattern is running: another can be loaded once it has ended.</source>
        <translation>图形正在运行：结束后才能加载另一个。</translation>
    </message>
    <message>
        <source>between two samples the path bends up to %1 µm away from the line joining them, more than the largest error found: what the machine did there is not seen</source>
        <translation>两个采样点之间，路径偏离其连线最多 %1 µm，大于测得的最大误差：机器在那里如何走看不到</translation>
    </message>
    <message numerus="yes">
        <source>%n samples say little of a largest error</source>
        <translation>
            <numerusform>只有 %n 个采样点，说明不了最大误差</numerusform>
        </translation>
    </message>
    <message>
        <source>Too few samples for this figure: %1.</source>
        <translation>采样点太少，此数值意义不大：%1。</translation>
    </message>
</context>
<context>
    <name>ui::PlateMap</name>
    <message>
        <source>%1 · plate (%2, %3) mm · machine (%4, %5) mm%6</source>
        <translation>%1 · 孔板坐标 (%2, %3) mm · 机器坐标 (%4, %5) mm%6</translation>
    </message>
    <message>
        <source> (nominal: slot not calibrated)</source>
        <translation>（名义位置：板位未校准）</translation>
    </message>
    <message>
        <source> · %1 µL dispensed</source>
        <translation> · 已排液 %1 µL</translation>
    </message>
    <message>
        <source> · %1 µL aspirated</source>
        <translation> · 已吸液 %1 µL</translation>
    </message>
    <message>
        <source> · visited, no net volume</source>
        <translation> · 已访问，净液量为零</translation>
    </message>
    <message>
        <source> · holds %1 µL</source>
        <translation> · 容积 %1 µL</translation>
    </message>
    <message>
        <source>No plate</source>
        <translation>无孔板</translation>
    </message>
    <message>
        <source>  ·  %1 × %2 mm, drawn to scale</source>
        <translation>  ·  %1 × %2 mm，按比例绘制</translation>
    </message>
</context>
<context>
    <name>ui::PlatesScreen</name>
    <message>
        <source>Plate</source>
        <translation>孔板</translation>
    </message>
    <message>
        <source>unused</source>
        <translation>未使用</translation>
    </message>
    <message>
        <source>planned</source>
        <translation>已计划</translation>
    </message>
    <message>
        <source>current</source>
        <translation>当前</translation>
    </message>
    <message>
        <source>done</source>
        <translation>已完成</translation>
    </message>
    <message>
        <source>error</source>
        <translation>错误</translation>
    </message>
    <message>
        <source>Use for this step</source>
        <translation>用于此步骤</translation>
    </message>
    <message>
        <source>Set the selected step&apos;s wells (and plate) to the selection</source>
        <translation>把所选步骤的孔（及孔板）设为当前选中的孔</translation>
    </message>
    <message>
        <source>Aspirate from these</source>
        <translation>从这些孔吸液</translation>
    </message>
    <message>
        <source>Dispense into these</source>
        <translation>向这些孔排液</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>清除</translation>
    </message>
    <message>
        <source>Recipe</source>
        <translation>加样方案</translation>
    </message>
    <message>
        <source>Calibrate</source>
        <translation>校准</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>运行</translation>
    </message>
    <message>
        <source>Click a well or drag across wells to select them (Ctrl adds).</source>
        <translation>点击一个孔或拖动跨过多个孔以选中（按住 Ctrl 追加）。</translation>
    </message>
    <message>
        <source>%1 wells selected: %2</source>
        <translation>已选 %1 个孔：%2</translation>
    </message>
    <message>
        <source>Discard the changes to this recipe?</source>
        <translation>放弃对此加样方案的更改？</translation>
    </message>
    <message>
        <source>Open recipe</source>
        <translation>打开加样方案</translation>
    </message>
    <message>
        <source>Recipes (*.recipe.json *.json)</source>
        <translation>加样方案 (*.recipe.json *.json)</translation>
    </message>
    <message>
        <source>Save recipe</source>
        <translation>保存加样方案</translation>
    </message>
    <message>
        <source>Recipes (*.recipe.json)</source>
        <translation>加样方案 (*.recipe.json)</translation>
    </message>
    <message>
        <source>the slot calibration %1 cannot be read; the slots use their nominal places:
%2</source>
        <translation>无法读取板位校准 %1；各板位使用名义位置：
%2</translation>
    </message>
    <message>
        <source>slot calibration saved to %1</source>
        <translation>板位校准已保存到 %1</translation>
    </message>
    <message>
        <source>new recipe</source>
        <translation>新方案</translation>
    </message>
    <message>
        <source>opened %1</source>
        <translation>已打开 %1</translation>
    </message>
    <message>
        <source>saved %1</source>
        <translation>已保存 %1</translation>
    </message>
    <message>
        <source>the recipe has no steps</source>
        <translation>该方案没有步骤</translation>
    </message>
    <message>
        <source>%1 in slot %2: %3</source>
        <translation>%1，位于板位 %2：%3</translation>
    </message>
    <message>
        <source>use the selection in step %1</source>
        <translation>在步骤 %1 中使用所选孔</translation>
    </message>
    <message>
        <source>aspirate from the selection</source>
        <translation>从所选孔吸液</translation>
    </message>
    <message>
        <source>dispense into the selection</source>
        <translation>向所选孔排液</translation>
    </message>
    <message>
        <source>the recipe does not validate: see its problems</source>
        <translation>该方案未通过检查：请查看其问题</translation>
    </message>
    <message>
        <source>Resume from run log</source>
        <translation>从运行日志继续</translation>
    </message>
    <message>
        <source>Run logs (*.run.jsonl *.jsonl)</source>
        <translation>运行日志 (*.run.jsonl *.jsonl)</translation>
    </message>
    <message>
        <source>Import labware</source>
        <translation>导入耗材</translation>
    </message>
    <message>
        <source>Labware definitions (*.json)</source>
        <translation>耗材定义 (*.json)</translation>
    </message>
    <message>
        <source>%1 is not a plate definition BenchPilot can use:
%2</source>
        <translation>%1 不是 BenchPilot 可用的孔板定义：
%2</translation>
    </message>
    <message>
        <source>use imported labware %1</source>
        <translation>使用导入的耗材 %1</translation>
    </message>
    <message>
        <source>imported %1 (%2 wells) as %3</source>
        <translation>已将 %1（%2 个孔）导入为 %3</translation>
    </message>
    <message>
        <source>Held while a run is under way: the recipe that runs stays the recipe on screen</source>
        <translation>运行期间保持不变：正在运行的方案就是屏幕上的方案</translation>
    </message>
    <message>
        <source>A run is under way: the recipe and plate map stay as they are until it has finished or been aborted.</source>
        <translation>运行正在进行：方案和孔板图保持不变，直到运行完成或被中止。</translation>
    </message>
    <message>
        <source>samples</source>
        <comment>the name of a new recipe&apos;s plate</comment>
        <translation>样品</translation>
    </message>
    <message>
        <source>Run &quot;%1&quot;: %2 operations over %3 wells, about %4. The tip goes down to Z %5 mm; the analyzer moves on its own until the end (Pause, Abort, or Esc for the E-stop). Start?</source>
        <translation>运行“%1”：%2 项操作，涉及 %3 个孔，约 %4。加样针将下降到 Z %5 mm；分析仪将自行运动直到结束（可按“暂停”“中止”，或按 Esc 急停）。开始？</translation>
    </message>
    <message>
        <source>%1 was not opened: its problems are listed under Problems</source>
        <translation>未打开 %1：其问题列在“问题”中</translation>
    </message>
</context>
<context>
    <name>ui::PlotCursors</name>
    <message>
        <source>A</source>
        <translation>A</translation>
    </message>
    <message>
        <source>B</source>
        <translation>B</translation>
    </message>
</context>
<context>
    <name>ui::PlotStack</name>
    <message>
        <source>Time (s, 0 = newest sample)</source>
        <translation>时间（s，0 = 最新采样）</translation>
    </message>
</context>
<context>
    <name>ui::PlotToolbar</name>
    <message>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <source>Freeze the view; the instruments keep streaming and recording goes on</source>
        <translation>冻结视图；仪器继续发送数据，记录也继续进行</translation>
    </message>
    <message>
        <source>Auto Y</source>
        <translation>自动 Y</translation>
    </message>
    <message>
        <source>Fit each plot&apos;s value axes to what is visible (dragging or Ctrl+wheel on a plot turns it off)</source>
        <translation>使每个曲线图的数值轴适应可见数据（在曲线图上拖动或按 Ctrl+滚轮会关闭此功能）</translation>
    </message>
    <message>
        <source>Cursors</source>
        <translation>光标</translation>
    </message>
    <message>
        <source>Two time cursors A and B with Δt and Δy; drag them along the time axis</source>
        <translation>两个时间光标 A 和 B，显示 Δt 和 Δy；可沿时间轴拖动</translation>
    </message>
    <message>
        <source>XY</source>
        <translation>XY</translation>
    </message>
    <message>
        <source>Show the stage&apos;s XY path, commanded against measured</source>
        <translation>显示载物台的 XY 路径，指令与实测对比</translation>
    </message>
    <message>
        <source>+ Plot</source>
        <translation>+ 曲线图</translation>
    </message>
    <message>
        <source>− Plot</source>
        <translation>− 曲线图</translation>
    </message>
    <message>
        <source>Record…</source>
        <translation>记录…</translation>
    </message>
    <message>
        <source>Stream every plotted channel to a CSV file until stopped</source>
        <translation>将所有已绘制的通道持续写入 CSV 文件，直到停止</translation>
    </message>
    <message>
        <source>CSV…</source>
        <translation>CSV…</translation>
    </message>
    <message>
        <source>PNG…</source>
        <translation>PNG…</translation>
    </message>
    <message>
        <source>PDF…</source>
        <translation>PDF…</translation>
    </message>
    <message>
        <source>Window</source>
        <translation>时间窗</translation>
    </message>
    <message>
        <source>How much history the plots keep and show (1 s to 10 min)</source>
        <translation>曲线保留并显示的历史长度（1 s 到 10 min）</translation>
    </message>
    <message>
        <source>1 s</source>
        <translation>1 s</translation>
    </message>
    <message>
        <source>2 s</source>
        <translation>2 s</translation>
    </message>
    <message>
        <source>5 s</source>
        <translation>5 s</translation>
    </message>
    <message>
        <source>10 s</source>
        <translation>10 s</translation>
    </message>
    <message>
        <source>30 s</source>
        <translation>30 s</translation>
    </message>
    <message>
        <source>1 min</source>
        <translation>1 min</translation>
    </message>
    <message>
        <source>2 min</source>
        <translation>2 min</translation>
    </message>
    <message>
        <source>5 min</source>
        <translation>5 min</translation>
    </message>
    <message>
        <source>10 min</source>
        <translation>10 min</translation>
    </message>
    <message>
        <source>Rate</source>
        <translation>采样率</translation>
    </message>
    <message>
        <source>Sample rate asked of the instruments; the link may carry less (see the status line)</source>
        <translation>向仪器请求的采样率；链路实际能承载的可能更低（见状态栏）</translation>
    </message>
    <message>
        <source>%1 kHz</source>
        <translation>%1 kHz</translation>
    </message>
    <message>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <source>Add a plot below the others</source>
        <translation>在其他曲线图下方添加一个曲线图</translation>
    </message>
    <message>
        <source>Remove the plot chosen in the channel list</source>
        <translation>移除在通道列表中选中的曲线图</translation>
    </message>
    <message>
        <source>Export the visible range as CSV: the raw samples (decimated per pixel column above %1 samples)</source>
        <translation>将可见范围导出为 CSV：原始采样数据（超过 %1 个采样点时按像素列抽取）</translation>
    </message>
    <message>
        <source>Export the plots as a picture</source>
        <translation>将曲线导出为图片</translation>
    </message>
    <message>
        <source>Export the plots as a vector PDF</source>
        <translation>将曲线导出为矢量 PDF</translation>
    </message>
    <message>
        <source>History…</source>
        <translation>历史…</translation>
    </message>
    <message>
        <source>Export the recorded history as CSV: every instrument&apos;s positions and following errors since connection, whether plotted or not</source>
        <translation>将记录的历史导出为 CSV：各仪器自连接以来的位置和跟随误差，无论是否已绘制曲线</translation>
    </message>
    <message>
        <source>Last 30 s</source>
        <translation>最近 30 s</translation>
    </message>
    <message>
        <source>Last 1 min</source>
        <translation>最近 1 min</translation>
    </message>
    <message>
        <source>Last 2 min</source>
        <translation>最近 2 min</translation>
    </message>
    <message>
        <source>Everything recorded</source>
        <translation>全部记录</translation>
    </message>
</context>
<context>
    <name>ui::PlotsScreen</name>
    <message>
        <source>Paused: the time axis was moved. Resume returns to the live view.</source>
        <translation>已暂停：时间轴被移动过。按“继续”返回实时视图。</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>继续</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;: %2 · %3 samples</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;：%2 · %3 个采样点</translation>
    </message>
    <message>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <source>not streaming</source>
        <translation>未发送数据</translation>
    </message>
    <message>
        <source> · &lt;span style=&apos;color:#b71c1c&apos;&gt;&lt;b&gt;%1 lost&lt;/b&gt;&lt;/span&gt;</source>
        <translation> · &lt;span style=&apos;color:#b71c1c&apos;&gt;&lt;b&gt;丢失 %1&lt;/b&gt;&lt;/span&gt;</translation>
    </message>
    <message>
        <source> · 0 lost</source>
        <translation> · 丢失 0</translation>
    </message>
    <message>
        <source> · %1 not kept while paused</source>
        <translation> · 暂停期间有 %1 个未保留</translation>
    </message>
    <message>
        <source>&lt;b&gt;paused&lt;/b&gt;</source>
        <translation>&lt;b&gt;已暂停&lt;/b&gt;</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#b71c1c&apos;&gt;● recording %1 rows to %2&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#b71c1c&apos;&gt;● 正在将 %1 行记录到 %2&lt;/span&gt;</translation>
    </message>
    <message>
        <source>Export the visible range as CSV</source>
        <translation>将可见范围导出为 CSV</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
    <message>
        <source>Exported the decimated view (%1 rows, min/max per pixel column) to %2</source>
        <translation>已将抽取后的视图（%1 行，每像素列取最小/最大值）导出到 %2</translation>
    </message>
    <message>
        <source>Exported %1 rows of raw samples to %2</source>
        <translation>已将 %1 行原始采样数据导出到 %2</translation>
    </message>
    <message>
        <source>Export the plots as PNG</source>
        <translation>将曲线导出为 PNG</translation>
    </message>
    <message>
        <source>PNG pictures (*.png)</source>
        <translation>PNG 图片 (*.png)</translation>
    </message>
    <message>
        <source>Saved the plots to %1</source>
        <translation>已将曲线保存到 %1</translation>
    </message>
    <message>
        <source>Export the plots as PDF</source>
        <translation>将曲线导出为 PDF</translation>
    </message>
    <message>
        <source>PDF documents (*.pdf)</source>
        <translation>PDF 文档 (*.pdf)</translation>
    </message>
    <message>
        <source>● Stop recording</source>
        <translation>● 停止记录</translation>
    </message>
    <message>
        <source>Record…</source>
        <translation>记录…</translation>
    </message>
    <message>
        <source>Record telemetry to CSV</source>
        <translation>将遥测数据记录为 CSV</translation>
    </message>
    <message>
        <source>Recording %1 channels to %2</source>
        <translation>正在将 %1 个通道记录到 %2</translation>
    </message>
    <message>
        <source>Recorded %1 rows to %2</source>
        <translation>已将 %1 行记录到 %2</translation>
    </message>
    <message>
        <source>last %1 recorded</source>
        <translation>已记录最近 %1</translation>
    </message>
    <message>
        <source> (plotted channels only: the link carries no more)</source>
        <translation>（仅记录已绘制的通道：连接无法承载更多）</translation>
    </message>
    <message>
        <source>Export the recorded history as CSV</source>
        <translation>将记录的历史导出为 CSV</translation>
    </message>
    <message>
        <source>Exported %1 rows of recorded history (%2 channels) to %3</source>
        <translation>已将 %1 行记录的历史（%2 个通道）导出到 %3</translation>
    </message>
</context>
<context>
    <name>ui::PolarPlot</name>
    <message>
        <source>X about the centre (mm)</source>
        <translation>相对圆心的 X (mm)</translation>
    </message>
    <message>
        <source>Y about the centre (mm)</source>
        <translation>相对圆心的 Y (mm)</translation>
    </message>
    <message>
        <source>counter-clockwise</source>
        <translation>逆时针</translation>
    </message>
    <message>
        <source>clockwise</source>
        <translation>顺时针</translation>
    </message>
    <message>
        <source>deviation magnified %1×</source>
        <translation>偏差放大 %1×</translation>
    </message>
</context>
<context>
    <name>ui::ProfilesScreen</name>
    <message>
        <source>Match 0 cannot fire: edge moved one tick late, the next step one tick early</source>
        <translation>比较值 0 无法触发：该边沿推迟一个计数，下一步提前一个计数</translation>
    </message>
    <message>
        <source>Rate outside 80 Hz … 20 kHz: clamped</source>
        <translation>频率超出 80 Hz … 20 kHz：已限幅</translation>
    </message>
    <message>
        <source>clamped</source>
        <translation>已限幅</translation>
    </message>
    <message>
        <source>+1 tick</source>
        <translation>+1 计数</translation>
    </message>
    <message>
        <source>Ideal period (µs)</source>
        <translation>理想周期 (µs)</translation>
    </message>
    <message>
        <source>Period (ticks)</source>
        <translation>周期（计数）</translation>
    </message>
    <message>
        <source>Whole periods</source>
        <translation>完整周期数</translation>
    </message>
    <message>
        <source>Match (ticks)</source>
        <translation>比较值（计数）</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>备注</translation>
    </message>
    <message>
        <source>Motion profiles</source>
        <translation>速度曲线</translation>
    </message>
    <message>
        <source>Seed S-curve (seed 000)</source>
        <translation>S 型加减速（文献 000）</translation>
    </message>
    <message>
        <source>Trapezoid with plateau steps (seed 001)</source>
        <translation>带平台段的梯形速度曲线（文献 001）</translation>
    </message>
    <message>
        <source>Exponential (seed 003)</source>
        <translation>指数型（文献 003）</translation>
    </message>
    <message>
        <source>Jerk-limited, time-optimal</source>
        <translation>限加加速度的时间最优曲线</translation>
    </message>
    <message>
        <source>Shape of the speed change</source>
        <translation>速度变化的形状</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>类型</translation>
    </message>
    <message>
        <source>Distance</source>
        <translation>距离</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Signed length of the move</source>
        <translation>移动的有符号长度</translation>
    </message>
    <message>
        <source>Max velocity</source>
        <translation>最大速度</translation>
    </message>
    <message>
        <source> mm/s</source>
        <translation> mm/s</translation>
    </message>
    <message>
        <source>Cruise speed the move may not exceed</source>
        <translation>移动时不得超过的巡航速度</translation>
    </message>
    <message>
        <source>Max acceleration</source>
        <translation>最大加速度</translation>
    </message>
    <message>
        <source> mm/s²</source>
        <translation> mm/s²</translation>
    </message>
    <message>
        <source>Acceleration limit (the trapezoid uses it for both ramps)</source>
        <translation>加速度限值（梯形曲线的加速段和减速段都用它）</translation>
    </message>
    <message>
        <source>Max jerk</source>
        <translation>最大加加速度</translation>
    </message>
    <message>
        <source> mm/s³</source>
        <translation> mm/s³</translation>
    </message>
    <message>
        <source>How fast the acceleration may change</source>
        <translation>加速度允许变化的快慢</translation>
    </message>
    <message>
        <source>Acceleration time</source>
        <translation>加速时间</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Seed S-curve: ramp duration t2. Exponential: reaches 95 % of the max velocity (3τ)</source>
        <translation>S 型加减速（文献 000）：加速段时长 t2。指数型：达到最大速度 95 %（3τ）所需的时间</translation>
    </message>
    <message>
        <source>Start speed</source>
        <translation>起始速度</translation>
    </message>
    <message>
        <source>Speed the motor can jump to from rest (seed 001 start speed)</source>
        <translation>电机可从静止直接跳到的速度（文献 001 的起始速度）</translation>
    </message>
    <message>
        <source>Plateau</source>
        <translation>平台段</translation>
    </message>
    <message>
        <source>Distance run at the start speed before accelerating and after braking (seed 001 plateau steps)</source>
        <translation>加速前和制动后以起始速度运行的距离（文献 001 的平台步数）</translation>
    </message>
    <message>
        <source>Step size</source>
        <translation>步距</translation>
    </message>
    <message>
        <source>Travel per (micro)step, for the step-period table</source>
        <translation>每（微）步的行程，用于步进周期表</translation>
    </message>
    <message>
        <source>s (mm)</source>
        <translation>s (mm)</translation>
    </message>
    <message>
        <source>v (mm/s)</source>
        <translation>v (mm/s)</translation>
    </message>
    <message>
        <source>a (mm/s²)</source>
        <translation>a (mm/s²)</translation>
    </message>
    <message>
        <source>j (mm/s³)</source>
        <translation>j (mm/s³)</translation>
    </message>
    <message>
        <source>t (s)</source>
        <translation>t (s)</translation>
    </message>
    <message>
        <source>Cannot plan this move: %1</source>
        <translation>无法规划此移动：%1</translation>
    </message>
    <message>
        <source>Move time: —</source>
        <translation>移动时间：—</translation>
    </message>
    <message>
        <source>Move time: %1 s</source>
        <translation>移动时间：%1 s</translation>
    </message>
    <message>
        <source>Peak velocity %1 mm/s · peak acceleration %2 mm/s² · peak jerk %3 mm/s³</source>
        <translation>峰值速度 %1 mm/s · 峰值加速度 %2 mm/s² · 峰值加加速度 %3 mm/s³</translation>
    </message>
    <message>
        <source>%1 steps: too many for the table (at most %2); use a larger step size.</source>
        <translation>%1 步：超出表格容量（最多 %2）；请使用更大的步距。</translation>
    </message>
    <message>
        <source>Step periods at %1 MHz, %2 µs interrupt (%3 ticks): %4 steps, table time %5 s vs ideal %6 s (error %7 µs), %8 clamped to 80 Hz … 20 kHz, %9 zero-match corrections.</source>
        <translation>步进周期（%1 MHz 时钟，%2 µs 中断，%3 个计数）：%4 步，表格时间 %5 s，理想时间 %6 s（误差 %7 µs），%8 个被限幅到 80 Hz … 20 kHz，%9 次零比较值修正。</translation>
    </message>
</context>
<context>
    <name>ui::RecipeEditor</name>
    <message>
        <source>New</source>
        <translation>新建</translation>
    </message>
    <message>
        <source>A new recipe with one 96-well plate in slot 1</source>
        <translation>新建加样方案，板位 1 放一块 96 孔板</translation>
    </message>
    <message>
        <source>Open…</source>
        <translation>打开…</translation>
    </message>
    <message>
        <source>Open a recipe file (Ctrl+O)</source>
        <translation>打开加样方案文件（Ctrl+O）</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>保存</translation>
    </message>
    <message>
        <source>Save the recipe (Ctrl+S)</source>
        <translation>保存加样方案（Ctrl+S）</translation>
    </message>
    <message>
        <source>Save as…</source>
        <translation>另存为…</translation>
    </message>
    <message>
        <source>Save the recipe under another name</source>
        <translation>以另一个名称保存加样方案</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>撤销</translation>
    </message>
    <message>
        <source>Undo the last change (Ctrl+Z)</source>
        <translation>撤销上一次更改（Ctrl+Z）</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>重做</translation>
    </message>
    <message>
        <source>Redo (Ctrl+Shift+Z)</source>
        <translation>重做（Ctrl+Shift+Z）</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>名称</translation>
    </message>
    <message>
        <source>Plates on the deck</source>
        <translation>台面上的孔板</translation>
    </message>
    <message>
        <source>Slot</source>
        <translation>板位</translation>
    </message>
    <message>
        <source>Labware</source>
        <translation>耗材</translation>
    </message>
    <message>
        <source>Safe Z (mm)</source>
        <translation>安全 Z (mm)</translation>
    </message>
    <message>
        <source>Depth Z (mm)</source>
        <translation>深度 Z (mm)</translation>
    </message>
    <message>
        <source>Add plate</source>
        <translation>添加孔板</translation>
    </message>
    <message>
        <source>Remove plate</source>
        <translation>移除孔板</translation>
    </message>
    <message>
        <source>Import Opentrons labware…</source>
        <translation>导入 Opentrons 耗材…</translation>
    </message>
    <message>
        <source>Read an Opentrons labware definition (schema 2), save it as a BenchPilot plate file beside the recipe, and use it for the selected plate</source>
        <translation>读取 Opentrons 耗材定义（第 2 版），在方案旁保存为 BenchPilot 孔板文件，并用于所选孔板</translation>
    </message>
    <message>
        <source>Steps</source>
        <translation>步骤</translation>
    </message>
    <message>
        <source>Add step</source>
        <translation>添加步骤</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>复制</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>移除</translation>
    </message>
    <message>
        <source>▲</source>
        <translation>▲</translation>
    </message>
    <message>
        <source>▼</source>
        <translation>▼</translation>
    </message>
    <message>
        <source>Move the step up</source>
        <translation>上移该步骤</translation>
    </message>
    <message>
        <source>Move the step down</source>
        <translation>下移该步骤</translation>
    </message>
    <message>
        <source>Problems</source>
        <translation>问题</translation>
    </message>
    <message>
        <source>rename the recipe</source>
        <translation>重命名方案</translation>
    </message>
    <message>
        <source>add a plate</source>
        <translation>添加孔板</translation>
    </message>
    <message>
        <source>remove plate %1</source>
        <translation>移除孔板 %1</translation>
    </message>
    <message>
        <source>change %1 of step %2</source>
        <translation>更改步骤 %2 的%1</translation>
    </message>
    <message>
        <source>duplicate step %1</source>
        <translation>复制步骤 %1</translation>
    </message>
    <message>
        <source>remove step %1</source>
        <translation>移除步骤 %1</translation>
    </message>
    <message>
        <source>station %1</source>
        <translation>工位 %1</translation>
    </message>
    <message>
        <source> %1 s</source>
        <translation> %1 s</translation>
    </message>
    <message>
        <source> %1 mm</source>
        <translation> %1 mm</translation>
    </message>
    <message>
        <source> %1 µL × %2</source>
        <translation> %1 µL × %2</translation>
    </message>
    <message>
        <source> %1 µL</source>
        <translation> %1 µL</translation>
    </message>
    <message>
        <source> ← %1</source>
        <translation> ← %1</translation>
    </message>
    <message>
        <source>rename a plate</source>
        <translation>重命名孔板</translation>
    </message>
    <message>
        <source>move a plate to slot %1</source>
        <translation>将孔板移到板位 %1</translation>
    </message>
    <message>
        <source>A built-in plate, or a labware file beside the recipe (NAME.labware.json, or an Opentrons definition)</source>
        <translation>内置孔板，或方案旁的耗材文件（NAME.labware.json 或 Opentrons 耗材定义）</translation>
    </message>
    <message>
        <source>change a plate&apos;s labware</source>
        <translation>更改孔板的耗材</translation>
    </message>
    <message>
        <source>Machine Z at which the tip clears this plate (Z counts down from home)</source>
        <translation>加样针越过此孔板所需的机器 Z 坐标（Z 从零位向下计数）</translation>
    </message>
    <message>
        <source>Machine Z the tip goes down to in a well</source>
        <translation>加样针在孔中下降到的机器 Z 坐标</translation>
    </message>
    <message>
        <source>change a safe height</source>
        <translation>更改安全高度</translation>
    </message>
    <message>
        <source>change a depth</source>
        <translation>更改深度</translation>
    </message>
    <message>
        <source>add step: %1</source>
        <translation>添加步骤：%1</translation>
    </message>
    <message>
        <source>move step %1</source>
        <translation>移动步骤 %1</translation>
    </message>
    <message>
        <source>The recipe validates.</source>
        <translation>加样方案检查通过。</translation>
    </message>
    <message>
        <source>Slot %1 is not on this deck: choose one of its slots</source>
        <translation>板位 %1 不在此台面上：请选择台面上的一个板位</translation>
    </message>
    <message>
        <source>%1 (not on this deck)</source>
        <translation>%1（不在此台面上）</translation>
    </message>
    <message>
        <source>Safe Z</source>
        <translation>安全 Z</translation>
    </message>
    <message>
        <source>Depth Z</source>
        <translation>深度 Z</translation>
    </message>
    <message>
        <source>%1 was not opened (the recipe on screen is unchanged):</source>
        <translation>未打开 %1（屏幕上的加样方案未改变）：</translation>
    </message>
</context>
<context>
    <name>ui::ResponsePlot</name>
    <message>
        <source>time from the start [s]</source>
        <translation>距开始的时间 [s]</translation>
    </message>
    <message>
        <source>output − start</source>
        <translation>输出 − 初始值</translation>
    </message>
    <message>
        <source>position − start [%1]</source>
        <translation>位置 − 初始值 [%1]</translation>
    </message>
    <message>
        <source>controller output u</source>
        <translation>控制器输出 u</translation>
    </message>
    <message>
        <source>controller output u [%1]</source>
        <translation>控制器输出 u [%1]</translation>
    </message>
</context>
<context>
    <name>ui::RunPanel</name>
    <message>
        <source>Run</source>
        <translation>运行</translation>
    </message>
    <message>
        <source>Run the recipe from its first well, logging every well (F5)</source>
        <translation>从第一个孔开始运行加样方案，记录每个孔（F5）</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <source>Stop after the well under way, with the tip up</source>
        <translation>完成当前孔后停止，加样针抬起</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>继续</translation>
    </message>
    <message>
        <source>Continue a paused or stopped run</source>
        <translation>继续已暂停或已停止的运行</translation>
    </message>
    <message>
        <source>Abort</source>
        <translation>中止</translation>
    </message>
    <message>
        <source>Stop at once, then raise the tip; the log can resume it later</source>
        <translation>立即停止，然后抬起加样针；之后可从日志继续</translation>
    </message>
    <message>
        <source>Resume from log…</source>
        <translation>从日志继续…</translation>
    </message>
    <message>
        <source>Continue a run that ended early (a crash, a pulled cable) from its run log: wells already done are not done again</source>
        <translation>从运行日志继续提前结束的运行（如程序崩溃、线缆被拔出）：已完成的孔不会重做</translation>
    </message>
    <message>
        <source>#</source>
        <translation>#</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>步骤</translation>
    </message>
    <message>
        <source>What</source>
        <translation>动作</translation>
    </message>
    <message>
        <source>Where</source>
        <translation>位置</translation>
    </message>
    <message>
        <source>X (mm)</source>
        <translation>X (mm)</translation>
    </message>
    <message>
        <source>Y (mm)</source>
        <translation>Y (mm)</translation>
    </message>
    <message>
        <source>Plunger (µL)</source>
        <translation>柱塞 (µL)</translation>
    </message>
    <message>
        <source>Starts at</source>
        <translation>开始时间</translation>
    </message>
    <message>
        <source>Not runnable: %1</source>
        <translation>无法运行：%1</translation>
    </message>
    <message>
        <source>State: %1</source>
        <translation>状态：%1</translation>
    </message>
    <message>
        <source>Current: %1</source>
        <translation>当前：%1</translation>
    </message>
    <message>
        <source>Current: —</source>
        <translation>当前：—</translation>
    </message>
    <message>
        <source>Elapsed %1 · ETA %2</source>
        <translation>已用时 %1 · 预计剩余 %2</translation>
    </message>
    <message>
        <source>done</source>
        <translation>已完成</translation>
    </message>
    <message>
        <source>Abort the run? The analyzer stops at once and raises the tip; the wells not done yet stay undone (the run log can resume them later).</source>
        <translation>中止运行？分析仪立即停止并抬起加样针；尚未完成的孔保持未完成（之后可从运行日志继续）。</translation>
    </message>
    <message>
        <source>Plan: what the run does, op by op</source>
        <translation>计划：运行逐项执行的操作</translation>
    </message>
    <message>
        <source>%1 operations over %2 wells · %3 µL dispensed, %4 µL aspirated · plunger %5 → %6 µL · about %7</source>
        <translation>%1 项操作，涉及 %2 个孔 · 排液 %3 µL，吸液 %4 µL · 柱塞 %5 → %6 µL · 约 %7</translation>
    </message>
    <message>
        <source>%1 of %2 operations</source>
        <translation>%1/%2 项操作</translation>
    </message>
    <message>
        <source>Next: %1</source>
        <translation>下一步：%1</translation>
    </message>
    <message>
        <source>The bound is the least time any controller could take for these wells in this order under the axes&apos; limits and the travel rules (docs/recipes.md)</source>
        <translation>下限是任何控制器在各轴限制和移动规则下按此顺序完成这些孔所需的最短时间（docs/recipes.md）</translation>
    </message>
    <message>
        <source>Well order</source>
        <translation>孔顺序</translation>
    </message>
    <message>
        <source>Planned</source>
        <translation>计划</translation>
    </message>
    <message>
        <source>Bound</source>
        <translation>下限</translation>
    </message>
    <message>
        <source>Planned / bound</source>
        <translation>计划 / 下限</translation>
    </message>
    <message>
        <source>Every step with wells planned in each order; the recipe&apos;s own order is the one shown above</source>
        <translation>每个含孔的步骤按各顺序规划；方案自身的顺序即上方所示</translation>
    </message>
    <message>
        <source>cannot be used</source>
        <translation>不能使用</translation>
    </message>
    <message>
        <source>Took %1 on the analyzer&apos;s clock: %2 times the time-optimal bound (%3); planned %4</source>
        <translation>按分析仪时钟用时 %1：是时间最优下限（%3）的 %2 倍；计划 %4</translation>
    </message>
    <message>
        <source>Time-optimal bound %1: the plan takes %2 times it</source>
        <translation>时间最优下限 %1：计划用时是它的 %2 倍</translation>
    </message>
</context>
<context>
    <name>ui::ScanPlanForm</name>
    <message>
        <source>corner %1 (&quot;%2&quot;) is not &quot;x, y&quot; in mm</source>
        <translation>角点 %1（“%2”）不是以 mm 为单位的“x, y”</translation>
    </message>
    <message>
        <source>What the scan is called in its files</source>
        <translation>扫描在其文件中使用的名称</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>名称</translation>
    </message>
    <message>
        <source>Two corners</source>
        <translation>两个角点</translation>
    </message>
    <message>
        <source>Centre and size</source>
        <translation>中心与尺寸</translation>
    </message>
    <message>
        <source>Polygon</source>
        <translation>多边形</translation>
    </message>
    <message>
        <source>Drag on the map to draw a rectangle; in Polygon mode click its corners and double-click to close</source>
        <translation>在地图上拖动以绘制矩形；在多边形模式下依次点击各角点，双击闭合</translation>
    </message>
    <message>
        <source>Region</source>
        <translation>区域</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>First corner, X</source>
        <translation>第一个角点 X</translation>
    </message>
    <message>
        <source>First corner, Y</source>
        <translation>第一个角点 Y</translation>
    </message>
    <message>
        <source>Opposite corner, X</source>
        <translation>对角点 X</translation>
    </message>
    <message>
        <source>Opposite corner, Y</source>
        <translation>对角点 Y</translation>
    </message>
    <message>
        <source>Corner X, Y</source>
        <translation>角点 X, Y</translation>
    </message>
    <message>
        <source>Opposite X, Y</source>
        <translation>对角点 X, Y</translation>
    </message>
    <message>
        <source>Centre of the region, X</source>
        <translation>区域中心 X</translation>
    </message>
    <message>
        <source>Centre of the region, Y</source>
        <translation>区域中心 Y</translation>
    </message>
    <message>
        <source>Width of the region (X)</source>
        <translation>区域宽度 (X)</translation>
    </message>
    <message>
        <source>Height of the region (Y)</source>
        <translation>区域高度 (Y)</translation>
    </message>
    <message>
        <source>Centre X, Y</source>
        <translation>中心 X, Y</translation>
    </message>
    <message>
        <source>Width, height</source>
        <translation>宽度, 高度</translation>
    </message>
    <message>
        <source>x, y; x, y; x, y …</source>
        <translation>x, y; x, y; x, y …</translation>
    </message>
    <message>
        <source>The outline&apos;s corners in mm, in order; click them on the map instead</source>
        <translation>轮廓的各角点（mm），按顺序排列；也可在地图上点击</translation>
    </message>
    <message>
        <source>Corners (x, y mm; …), or click them on the map:</source>
        <translation>角点（x, y mm; …），或在地图上点击：</translation>
    </message>
    <message>
        <source>Scan and region</source>
        <translation>扫描与区域</translation>
    </message>
    <message>
        <source>Sensor and objective</source>
        <translation>传感器与物镜</translation>
    </message>
    <message>
        <source>Field size</source>
        <translation>视场尺寸</translation>
    </message>
    <message>
        <source>Field from</source>
        <translation>视场来源</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source>Sensor width in pixels</source>
        <translation>传感器宽度（像素）</translation>
    </message>
    <message>
        <source>Sensor height in pixels</source>
        <translation>传感器高度（像素）</translation>
    </message>
    <message>
        <source>Sensor</source>
        <translation>传感器</translation>
    </message>
    <message>
        <source> µm</source>
        <translation> µm</translation>
    </message>
    <message>
        <source>Pixel pitch on the sensor</source>
        <translation>传感器上的像元尺寸</translation>
    </message>
    <message>
        <source>Pixel size</source>
        <translation>像元尺寸</translation>
    </message>
    <message>
        <source> ×</source>
        <translation> ×</translation>
    </message>
    <message>
        <source>Objective times any relay lens</source>
        <translation>物镜倍率乘以中继镜倍率</translation>
    </message>
    <message>
        <source>Magnification</source>
        <translation>放大倍率</translation>
    </message>
    <message>
        <source>Field width at the sample</source>
        <translation>样品处的视场宽度</translation>
    </message>
    <message>
        <source>Field height at the sample</source>
        <translation>样品处的视场高度</translation>
    </message>
    <message>
        <source>Field</source>
        <translation>视场</translation>
    </message>
    <message>
        <source>One pixel at the sample: the exports give positions in pixels</source>
        <translation>样品处一个像素的尺寸：导出文件以像素给出位置</translation>
    </message>
    <message>
        <source>Pixel at sample</source>
        <translation>样品处像素尺寸</translation>
    </message>
    <message>
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <source>The image&apos;s x axis against stage +X, counter-clockwise (a small calibration angle)</source>
        <translation>图像 x 轴相对载物台 +X 的夹角，逆时针为正（一个小的校准角）</translation>
    </message>
    <message>
        <source>Camera rotation</source>
        <translation>相机旋转角</translation>
    </message>
    <message>
        <source>down the image = stage −Y</source>
        <translation>图像向下 = 载物台 −Y</translation>
    </message>
    <message>
        <source>down the image = stage +Y</source>
        <translation>图像向下 = 载物台 +Y</translation>
    </message>
    <message>
        <source>Which way image rows run on the stage; flip it if the stitched mosaic comes out mirrored</source>
        <translation>图像行在载物台上的走向；若拼接后的图像呈镜像，请切换此项</translation>
    </message>
    <message>
        <source>Image rows</source>
        <translation>图像行方向</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>相机</translation>
    </message>
    <message>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <source>Share of the field neighbours overlap in X (0–90 %)</source>
        <translation>相邻视场在 X 方向的重叠比例（0–90 %）</translation>
    </message>
    <message>
        <source>Share of the field neighbours overlap in Y (0–90 %)</source>
        <translation>相邻视场在 Y 方向的重叠比例（0–90 %）</translation>
    </message>
    <message>
        <source>Overlap X, Y</source>
        <translation>重叠 X, Y</translation>
    </message>
    <message>
        <source>Snake by rows</source>
        <translation>按行蛇形</translation>
    </message>
    <message>
        <source>Snake by columns</source>
        <translation>按列蛇形</translation>
    </message>
    <message>
        <source>Row by row</source>
        <translation>逐行</translation>
    </message>
    <message>
        <source>Column by column</source>
        <translation>逐列</translation>
    </message>
    <message>
        <source>Order</source>
        <translation>顺序</translation>
    </message>
    <message>
        <source>Top left</source>
        <translation>左上</translation>
    </message>
    <message>
        <source>Top right</source>
        <translation>右上</translation>
    </message>
    <message>
        <source>Bottom left</source>
        <translation>左下</translation>
    </message>
    <message>
        <source>Bottom right</source>
        <translation>右下</translation>
    </message>
    <message>
        <source>Start corner</source>
        <translation>起始角点</translation>
    </message>
    <message>
        <source>Approach every tile from the same side</source>
        <translation>每个图块都从同一侧趋近</translation>
    </message>
    <message>
        <source>Takes up screw backlash the same way at every tile: a move the other way first goes past the tile by the overtravel</source>
        <translation>每个图块都以相同方向消除丝杠反向间隙：反方向的移动会先越过图块一个超程距离</translation>
    </message>
    <message>
        <source>How far before the tile the approach starts</source>
        <translation>趋近从图块之前多远处开始</translation>
    </message>
    <message>
        <source>Overtravel</source>
        <translation>超程</translation>
    </message>
    <message>
        <source>Tiles</source>
        <translation>图块</translation>
    </message>
    <message>
        <source> mm/s</source>
        <translation> mm/s</translation>
    </message>
    <message>
        <source>Path speed of the moves between tiles</source>
        <translation>图块之间移动的路径速度</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Expected settling per tile, for the time estimate</source>
        <translation>每个图块预计的稳定时间，用于估算用时</translation>
    </message>
    <message>
        <source>Settle (estimate)</source>
        <translation>稳定时间（估计）</translation>
    </message>
    <message>
        <source>The stage dwells this long at each tile</source>
        <translation>载物台在每个图块停留的时间</translation>
    </message>
    <message>
        <source>Exposure</source>
        <translation>曝光</translation>
    </message>
    <message>
        <source>A tile is taken once the grating reads this close to its target</source>
        <translation>光栅尺读数与目标位置相差在此范围内即采集图块</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>容差</translation>
    </message>
    <message>
        <source>A tile not settled by then stops the run with the reason</source>
        <translation>到时仍未稳定的图块会使扫描停止，并给出原因</translation>
    </message>
    <message>
        <source>Settle timeout</source>
        <translation>稳定超时</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>运行</translation>
    </message>
    <message>
        <source>{i} the tile&apos;s number, {row} and {col} its place; {i:03} pads to three digits</source>
        <translation>{i} 为图块序号，{row} 和 {col} 为其行列位置；{i:03} 补零到三位</translation>
    </message>
    <message>
        <source>File names</source>
        <translation>文件名</translation>
    </message>
    <message>
        <source>First number</source>
        <translation>起始序号</translation>
    </message>
    <message>
        <source>The XY stage&apos;s device label in Micro-Manager (for the .pos position list)</source>
        <translation>XY 载物台在 Micro-Manager 中的设备名（用于 .pos 位置列表）</translation>
    </message>
    <message>
        <source>Micro-Manager stage</source>
        <translation>Micro-Manager 载物台</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>导出</translation>
    </message>
    <message>
        <source>Field %1 × %2 mm, %3 µm per pixel at the sample</source>
        <translation>视场 %1 × %2 mm，样品处每像素 %3 µm</translation>
    </message>
    <message>
        <source>Use the stage&apos;s own compensation</source>
        <translation>使用载物台自身的补偿</translation>
    </message>
    <message>
        <source>Runs only when the stage has its error compensation enabled on X and Y: the stage moves each target so the work point lands on it. Measure and upload it on the Calibration screen.</source>
        <translation>仅当载物台的 X 和 Y 都已启用误差补偿时才能运行：载物台会修正每个目标位置，使工作点准确落在目标上。请在“校准”界面测量并上传补偿。</translation>
    </message>
    <message>
        <source>Field: — (a camera value above is not a number yet)</source>
        <translation>视场：—（上方某个相机数值还不是数字）</translation>
    </message>
    <message>
        <source>Pixel size, rotation and image rows come from the camera profile %1 when the plan is opened</source>
        <translation>打开此方案时，像素尺寸、旋转和图像行方向取自相机配置文件 %1</translation>
    </message>
</context>
<context>
    <name>ui::ScanScreen</name>
    <message>
        <source>Whole stage</source>
        <translation>整个载物台</translation>
    </message>
    <message>
        <source>Show the whole travel</source>
        <translation>显示整个行程</translation>
    </message>
    <message>
        <source>Zoom to scan</source>
        <translation>缩放到扫描区</translation>
    </message>
    <message>
        <source>Show the scan&apos;s tiles</source>
        <translation>显示扫描的图块</translation>
    </message>
    <message>
        <source>X %1  Y %2 mm</source>
        <translation>X %1  Y %2 mm</translation>
    </message>
    <message>
        <source>Scan finished: %1 tiles taken. Exports written to %2.</source>
        <translation>扫描完成：已采集 %1 个图块。导出文件已写入 %2。</translation>
    </message>
    <message>
        <source>New</source>
        <translation>新建</translation>
    </message>
    <message>
        <source>Start from the default plan</source>
        <translation>从默认计划开始</translation>
    </message>
    <message>
        <source>Open plan…</source>
        <translation>打开计划…</translation>
    </message>
    <message>
        <source>Open a scan plan file (%1)</source>
        <translation>打开扫描计划文件（%1）</translation>
    </message>
    <message>
        <source>Save plan…</source>
        <translation>保存计划…</translation>
    </message>
    <message>
        <source>Save this plan as a file (%1)</source>
        <translation>将此计划保存为文件（%1）</translation>
    </message>
    <message>
        <source>Open scan plan</source>
        <translation>打开扫描计划</translation>
    </message>
    <message>
        <source>Scan plans (*.scan.json *.json)</source>
        <translation>扫描计划 (*.scan.json *.json)</translation>
    </message>
    <message>
        <source>Save scan plan</source>
        <translation>保存扫描计划</translation>
    </message>
    <message>
        <source>Scan plans (*.scan.json)</source>
        <translation>扫描计划 (*.scan.json)</translation>
    </message>
    <message>
        <source>The run log and the exports go here; a run stopped part-way continues from its log</source>
        <translation>运行日志和导出文件保存在此处；中途停止的扫描可从其日志继续</translation>
    </message>
    <message>
        <source>Folder for the run log and exports</source>
        <translation>存放运行日志和导出文件的文件夹</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>输出</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>运行</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <source>Stop after the tile in progress (Ctrl+P)</source>
        <translation>完成当前图块后停止（Ctrl+P）</translation>
    </message>
    <message>
        <source>Abort</source>
        <translation>中止</translation>
    </message>
    <message>
        <source>Stop the stage now; the tiles taken are kept and Resume continues (Ctrl+Shift+A)</source>
        <translation>立即停止载物台；已采集的图块会保留，按“继续”可接着扫描（Ctrl+Shift+A）</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>导出</translation>
    </message>
    <message>
        <source>Write TileConfiguration.txt (Fiji), positions.pos (Micro-Manager) and scan.csv to the output folder</source>
        <translation>将 TileConfiguration.txt（Fiji）、positions.pos（Micro-Manager）和 scan.csv 写入输出文件夹</translation>
    </message>
    <message>
        <source>%v of %m tiles</source>
        <translation>%v/%m 个图块</translation>
    </message>
    <message>
        <source>Cannot open the plan:
%1</source>
        <translation>无法打开计划：
%1</translation>
    </message>
    <message>
        <source>Opened %1: %2 tiles.</source>
        <translation>已打开 %1：%2 个图块。</translation>
    </message>
    <message>
        <source>Saved the plan to %1.</source>
        <translation>计划已保存到 %1。</translation>
    </message>
    <message>
        <source>Polygon: %1</source>
        <translation>多边形：%1</translation>
    </message>
    <message>
        <source>No tiles: fix the plan below</source>
        <translation>没有图块：请修正下方的计划</translation>
    </message>
    <message>
        <source>%1 × %2</source>
        <translation>%1 × %2</translation>
    </message>
    <message>
        <source>%1 of %2 × %3 in the outline</source>
        <translation>%2 × %3 中有 %1 个位于轮廓内</translation>
    </message>
    <message>
        <source>%1 tiles (%2) · step %3 × %4 mm · about %5 (moves %6, settle %7, exposure %8) · travel %9 mm</source>
        <translation>%1 个图块（%2）· 步距 %3 × %4 mm · 约 %5（移动 %6，稳定 %7，曝光 %8）· 行程 %9 mm</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>继续</translation>
    </message>
    <message>
        <source>Run the scan on the stage, or continue it at the next tile (Ctrl+R)</source>
        <translation>在载物台上运行扫描，或从下一个图块继续（Ctrl+R）</translation>
    </message>
    <message>
        <source>The stage is not connected.</source>
        <translation>载物台未连接。</translation>
    </message>
    <message>
        <source>Ready. The run log and exports go to the output folder.</source>
        <translation>就绪。运行日志和导出文件将写入输出文件夹。</translation>
    </message>
    <message>
        <source>%1 · tile %2 of %3 · about %4 left</source>
        <translation>%1 · 第 %2 个图块（共 %3 个）· 约剩 %4</translation>
    </message>
    <message>
        <source>%1 · %2 of %3 tiles taken</source>
        <translation>%1 · 已采集 %2/%3 个图块</translation>
    </message>
    <message>
        <source>The plan has problems: %1</source>
        <translation>该计划有问题：%1</translation>
    </message>
    <message>
        <source>Choose an output folder for the run log and the exports.</source>
        <translation>请为运行日志和导出文件选择一个输出文件夹。</translation>
    </message>
    <message>
        <source>%1

Start this scan anew in that folder? The old run log is kept under another name.</source>
        <translation>%1

在该文件夹中重新开始此扫描？旧的运行日志将以另一个名称保留。</translation>
    </message>
    <message>
        <source>Every tile of this scan is already taken in %1. Take them all again? The old run log is kept under another name.</source>
        <translation>此扫描的所有图块均已在 %1 中采集。全部重新采集？旧的运行日志将以另一个名称保留。</translation>
    </message>
    <message>
        <source>The scan cannot start: %1</source>
        <translation>无法开始扫描：%1</translation>
    </message>
    <message>
        <source>Continue the scan at tile %1 of %2? About %3 are left.</source>
        <translation>从第 %1 个图块（共 %2 个）继续扫描？约剩 %3。</translation>
    </message>
    <message>
        <source>Run %1 tiles on the stage? It takes about %2, starting with a move to (%3, %4) mm.</source>
        <translation>在载物台上运行 %1 个图块？约需 %2，首先移动到（%3, %4）mm。</translation>
    </message>
    <message>
        <source>Continuing at tile %1 of %2 (the run log has the first %3).</source>
        <translation>从第 %1 个图块（共 %2 个）继续（运行日志中已有前 %3 个）。</translation>
    </message>
    <message>
        <source>The plan has problems: nothing to export.</source>
        <translation>该计划有问题：没有可导出的内容。</translation>
    </message>
    <message>
        <source>Export failed: %1</source>
        <translation>导出失败：%1</translation>
    </message>
    <message>
        <source>Exported %1 tiles with the positions measured so far to %2.</source>
        <translation>已将 %1 个图块及目前实测的位置导出到 %2。</translation>
    </message>
    <message>
        <source>Exported %1 planned tile positions to %2.</source>
        <translation>已将 %1 个计划图块位置导出到 %2。</translation>
    </message>
    <message>
        <source>The plan is not saved: %1</source>
        <translation>计划未保存：%1</translation>
    </message>
    <message>
        <source>Stage map</source>
        <translation>载物台地图</translation>
    </message>
    <message>
        <source>Take an image at each tile</source>
        <translation>在每个图块拍摄图像</translation>
    </message>
    <message>
        <source>The camera open on the Camera tab takes each tile once it has settled; the images go to the output folder</source>
        <translation>“相机”页中打开的相机在每个图块稳定后拍摄；图像保存到输出文件夹</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>相机</translation>
    </message>
    <message>
        <source>Open a camera on the Camera tab first, or clear “Take an image at each tile”.</source>
        <translation>请先在“相机”页打开相机，或取消“在每个图块拍摄图像”。</translation>
    </message>
    <message>
        <source>Mosaic</source>
        <translation>拼接图</translation>
    </message>
</context>
<context>
    <name>ui::ScanStageMap</name>
    <message>
        <source>Stage map</source>
        <translation>载物台地图</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <source>X →   Y ↑</source>
        <translation>X →   Y ↑</translation>
    </message>
</context>
<context>
    <name>ui::StepForm</name>
    <message>
        <source>A1:H1, row B, column 3, all, or a list: A1, C4</source>
        <translation>A1:H1、row B、column 3、all，或列表：A1, C4</translation>
    </message>
    <message>
        <source>Wells: a well (A1), a range (A1:H1), &quot;row B&quot;, &quot;column 3&quot;, &quot;all&quot;, or several separated by commas.
Select wells on the plate map and press &quot;Use selection&quot; to fill this in.</source>
        <translation>孔：单个孔（A1）、范围（A1:H1）、“row B”、“column 3”、“all”，或用逗号分隔的多项。
也可在孔板图上选择孔，然后按“用于此步骤”自动填入。</translation>
    </message>
    <message>
        <source> µL</source>
        <translation> µL</translation>
    </message>
    <message>
        <source>Per well (aspirate, dispense), per stroke (mix, wash), or the air gap</source>
        <translation>每孔（吸液、排液）、每次行程（混匀、清洗）或空气间隔的体积</translation>
    </message>
    <message>
        <source>set</source>
        <translation>指定</translation>
    </message>
    <message>
        <source> µL/s</source>
        <translation> µL/s</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Touch-off: how far from the well&apos;s centre toward its +x wall the tip goes</source>
        <translation>贴壁：加样针从孔中心向孔的 +x 壁移动的距离</translation>
    </message>
    <message>
        <source>well</source>
        <translation>孔</translation>
    </message>
    <message>
        <source>plate</source>
        <translation>孔板</translation>
    </message>
    <message>
        <source>or station</source>
        <translation>或工位</translation>
    </message>
    <message>
        <source>Refill from here before each round: a transfer bigger than the syringe runs in several rounds</source>
        <translation>每轮之前从此处补液：超过注射器容积的转移分多轮进行</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>类型</translation>
    </message>
    <message>
        <source>Plate</source>
        <translation>孔板</translation>
    </message>
    <message>
        <source>Wells</source>
        <translation>孔</translation>
    </message>
    <message>
        <source>Station</source>
        <translation>工位</translation>
    </message>
    <message>
        <source>Volume</source>
        <translation>体积</translation>
    </message>
    <message>
        <source>Pump speed</source>
        <translation>泵速</translation>
    </message>
    <message>
        <source>Cycles</source>
        <translation>次数</translation>
    </message>
    <message>
        <source>Wait</source>
        <translation>等待</translation>
    </message>
    <message>
        <source>Touch-off</source>
        <translation>贴壁</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>来源</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>备注</translation>
    </message>
    <message>
        <source>(the only plate)</source>
        <translation>（唯一的孔板）</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>（无）</translation>
    </message>
    <message>
        <source>Touch-off after each well</source>
        <translation>每个孔后贴壁</translation>
    </message>
</context>
<context>
    <name>ui::StepTestPanel</name>
    <message>
        <source>Step</source>
        <translation>阶跃</translation>
    </message>
    <message>
        <source>positive</source>
        <translation>正向</translation>
    </message>
    <message>
        <source>negative</source>
        <translation>负向</translation>
    </message>
    <message>
        <source>Run step test</source>
        <translation>运行阶跃测试</translation>
    </message>
    <message>
        <source>The target steps by this much under the gains in force; the response is added to the plot</source>
        <translation>目标位置在当前生效的增益下按此幅值阶跃；响应将添加到曲线中</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>清除</translation>
    </message>
    <message>
        <source> µm</source>
        <translation> µm</translation>
    </message>
    <message>
        <source>µm</source>
        <translation>µm</translation>
    </message>
    <message>
        <source>units</source>
        <translation>单位</translation>
    </message>
    <message>
        <source>Rise 10–90 % [ms]</source>
        <translation>上升时间 10–90 % [ms]</translation>
    </message>
    <message>
        <source>Overshoot [%]</source>
        <translation>超调量 [%]</translation>
    </message>
    <message>
        <source>Settling 2 % [ms]</source>
        <translation>调节时间 2 % [ms]</translation>
    </message>
    <message>
        <source>Steady error [%1]</source>
        <translation>稳态误差 [%1]</translation>
    </message>
    <message>
        <source>IAE [%1·s]</source>
        <translation>IAE [%1·s]</translation>
    </message>
    <message>
        <source>ISE [(%1)²·s]</source>
        <translation>ISE [(%1)²·s]</translation>
    </message>
    <message>
        <source>Peak output [%1]</source>
        <translation>峰值输出 [%1]</translation>
    </message>
    <message>
        <source>Inside ±5 µm from [ms]</source>
        <translation>进入 ±5 µm 的时间 [ms]</translation>
    </message>
    <message>
        <source>Ended</source>
        <translation>结束原因</translation>
    </message>
    <message>
        <source>never</source>
        <translation>从未</translation>
    </message>
    <message>
        <source>unstable</source>
        <translation>不稳定</translation>
    </message>
    <message>
        <source>did not settle</source>
        <translation>未稳定</translation>
    </message>
    <message>
        <source>Limit cycle at rest</source>
        <translation>静止时的极限环</translation>
    </message>
    <message>
        <source>±%1 %2 every %3 ms</source>
        <translation>±%1 %2，周期 %3 ms</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>never: limit cycle</source>
        <translation>从未稳定：极限环</translation>
    </message>
</context>
<context>
    <name>ui::StitchPanel</name>
    <message>
        <source>Stitching failed.</source>
        <translation>拼接失败。</translation>
    </message>
    <message>
        <source>Stitching %1 failed: %2</source>
        <translation>拼接 %1 失败：%2</translation>
    </message>
    <message>
        <source>%1 tiles, %2 pairs: %3 trusted, %4 rejected as outliers, %5 not trusted; %6 tiles placed by the stage (hatched)</source>
        <translation>%1 个图块，%2 对：%3 对可信，%4 对作为离群值剔除，%5 对不可信；%6 个图块按载物台位置放置（斜线）</translation>
    </message>
    <message>
        <source>Correction from the stage: RMS %1 px (%2 µm), worst %3 px (%4 µm); arrows drawn ×%5</source>
        <translation>相对载物台位置的修正：均方根 %1 像素（%2 µm），最大 %3 像素（%4 µm）；箭头放大 %5 倍</translation>
    </message>
    <message>
        <source>Mosaic %1 × %2 px in %3 s</source>
        <translation>拼接图 %1 × %2 像素，用时 %3 秒</translation>
    </message>
    <message>
        <source>The quality map could not be written to %1: %2</source>
        <translation>无法把质量图写入 %1：%2</translation>
    </message>
    <message>
        <source>Stitched live during the scan: placed %1 s after the last tile, the files written %2 s after it</source>
        <translation>扫描期间实时拼接：最后一个图块后 %1 秒完成全局定位，%2 秒后文件写完</translation>
    </message>
    <message>
        <source>%v of %m tiles</source>
        <translation>%v / %m 个图块</translation>
    </message>
    <message>
        <source>Stitching live as the scan takes the tiles: %1 of %2 registered</source>
        <translation>随扫描采集图块实时拼接：已配准 %1 / %2 个</translation>
    </message>
    <message>
        <source>The scan stopped: nothing is written; the live mosaic begins again when the scan resumes.</source>
        <translation>扫描已停止：未写出任何文件；扫描继续时实时拼接图重新开始。</translation>
    </message>
    <message>
        <source>Stitched into %1: %2</source>
        <translation>已拼接到 %1：%2</translation>
    </message>
    <message>
        <source>Tile %1 (%2): moved %3, %4 px from where the stage put it%5</source>
        <translation>图块 %1（%2）：相对载物台位置移动了 %3, %4 像素%5</translation>
    </message>
    <message>
        <source>; no trusted pair: placed by the stage</source>
        <translation>；没有可信的图块对：按载物台位置放置</translation>
    </message>
    <message>
        <source>with tile %1: shift %2, %3 px, score %4, %5</source>
        <translation>与图块 %1：位移 %2, %3 像素，得分 %4，%5</translation>
    </message>
    <message>
        <source>Stitching %1 tiles in %2…</source>
        <translation>正在拼接 %2 中的 %1 个图块…</translation>
    </message>
    <message>
        <source>A scan is running into the folder: stitch it when it has finished.</source>
        <translation>扫描正在写入该文件夹：请在扫描结束后再拼接。</translation>
    </message>
    <message>
        <source>Stitch</source>
        <translation>拼接</translation>
    </message>
    <message>
        <source>Stitch the images of the scan in the output folder into a mosaic (Ctrl+T)</source>
        <translation>把输出文件夹中扫描的图像拼接成拼接图（Ctrl+T）</translation>
    </message>
    <message>
        <source>Check the plan&apos;s camera: %1</source>
        <translation>请检查计划中的相机：%1</translation>
    </message>
    <message>
        <source>Correction from the stage: RMS %1 px (%2 µm), worst %3 px (%4 µm)</source>
        <translation>相对载物台位置的修正：RMS %1 px（%2 µm），最大 %3 px（%4 µm）</translation>
    </message>
    <message>
        <source>Stage against camera, fitted from %1 pairs: scale x %2 ppm, y %3 ppm, shear %4 µrad; beyond it RMS %5 px (%6 µm), worst %7 px, as the arrows show ×%8</source>
        <translation>载物台相对相机（由 %1 对拟合）：x 比例 %2 ppm，y 比例 %3 ppm，剪切 %4 µrad；模型之外 RMS %5 px（%6 µm），最大 %7 px，箭头放大 ×%8 显示</translation>
    </message>
</context>
<context>
    <name>ui::TravelView</name>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <source>XY travel to scale · dashed: soft limits</source>
        <translation>XY 行程（按比例）· 虚线：软限位</translation>
    </message>
    <message>
        <source>not connected: the grey ring is the last known position</source>
        <translation>未连接：灰色圆圈是最后已知的位置</translation>
    </message>
</context>
<context>
    <name>ui::TuningScreen</name>
    <message>
        <source>Tune</source>
        <translation>整定</translation>
    </message>
    <message>
        <source>fopdt:K=..,tau=..,L=.. or lag:K=..,tau=..,n=.. (times in s; Ts=.. sets the loop period, 10 kHz unless given)</source>
        <translation>fopdt:K=..,tau=..,L=.. 或 lag:K=..,tau=..,n=..（时间单位为 s；Ts=.. 设定控制周期，未给出时为 10 kHz）</translation>
    </message>
    <message>
        <source>Open results…</source>
        <translation>打开结果…</translation>
    </message>
    <message>
        <source>Save results…</source>
        <translation>保存结果…</translation>
    </message>
    <message>
        <source>Step test</source>
        <translation>阶跃测试</translation>
    </message>
    <message>
        <source>Ziegler–Nichols assistant</source>
        <translation>Ziegler–Nichols 整定助手</translation>
    </message>
    <message>
        <source>idle</source>
        <translation>空闲</translation>
    </message>
    <message>
        <source>Abort</source>
        <translation>中止</translation>
    </message>
    <message>
        <source>Kp</source>
        <translation>Kp</translation>
    </message>
    <message>
        <source>Ki</source>
        <translation>Ki</translation>
    </message>
    <message>
        <source>Kd</source>
        <translation>Kd</translation>
    </message>
    <message>
        <source>%1 %2 → %3 (%4×)</source>
        <translation>%1 %2 → %3（%4 倍）</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>继续</translation>
    </message>
    <message>
        <source>Run the interrupted experiment again once the link is back</source>
        <translation>连接恢复后重新运行被中断的试验</translation>
    </message>
    <message>
        <source>saved as power-up gains</source>
        <translation>已保存为上电增益</translation>
    </message>
    <message>
        <source>Apply these gains to %1?
%2</source>
        <translation>将这些增益应用到%1？
%2</translation>
    </message>
    <message>
        <source>live at %1 Hz%2; the analysis reads the device&apos;s capture at the loop rate</source>
        <translation>实时 %1 Hz%2；分析读取设备以控制频率采集的数据</translation>
    </message>
    <message>
        <source>no target</source>
        <translation>无对象</translation>
    </message>
    <message>
        <source>model defaults</source>
        <translation>模型默认值</translation>
    </message>
    <message>
        <source>This plant cannot be tuned by Ziegler–Nichols: %1.</source>
        <translation>该对象无法用 Ziegler–Nichols 法整定：%1。</translation>
    </message>
    <message>
        <source>reading the gains of %1…</source>
        <translation>正在读取%1的增益…</translation>
    </message>
    <message>
        <source>read from the device</source>
        <translation>从设备读取</translation>
    </message>
    <message>
        <source>These gains are far from the ones %1 runs now:
%2
A loop this different may oscillate or run away. Apply them?</source>
        <translation>这些增益与 %1 当前运行的增益相差很大：
%2
差别这么大的回路可能振荡或失控。仍要应用吗？</translation>
    </message>
    <message>
        <source>%1: gains applied (%2)</source>
        <translation>%1：已应用增益（%2）</translation>
    </message>
    <message>
        <source>running…</source>
        <translation>运行中…</translation>
    </message>
    <message>
        <source>cannot resume yet: the link must be back (connect the instrument) and the same target chosen</source>
        <translation>暂不能继续：须恢复连接（连接仪器）并选择同一对象</translation>
    </message>
    <message>
        <source>live: %1</source>
        <translation>实时：%1</translation>
    </message>
    <message>
        <source>Save tuning results</source>
        <translation>保存整定结果</translation>
    </message>
    <message>
        <source>Tuning results (*.tuning.json)</source>
        <translation>整定结果 (*.tuning.json)</translation>
    </message>
    <message>
        <source>tuning results saved to %1</source>
        <translation>整定结果已保存到 %1</translation>
    </message>
    <message>
        <source>A tuning run is under way: results can be opened once it has ended.</source>
        <translation>整定正在进行：结束后才能打开结果。</translation>
    </message>
    <message>
        <source>Open tuning results</source>
        <translation>打开整定结果</translation>
    </message>
    <message>
        <source>results of %1 loaded</source>
        <translation>已载入%1的结果</translation>
    </message>
    <message>
        <source>results of %1 loaded; the rules&apos; gains are for its loop period (%2 ms), applied to %3 as they are</source>
        <translation>已载入%1的结果；各规则的增益对应其控制周期（%2 ms），按原值应用到%3</translation>
    </message>
    <message>
        <source>Model plant</source>
        <translation>模型对象</translation>
    </message>
</context>
<context>
    <name>ui::XyView</name>
    <message>
        <source>measured</source>
        <translation>实测</translation>
    </message>
    <message>
        <source>commanded</source>
        <translation>指令</translation>
    </message>
    <message>
        <source>now</source>
        <translation>当前</translation>
    </message>
    <message>
        <source>XY path</source>
        <translation>XY 路径</translation>
    </message>
    <message>
        <source>X</source>
        <translation>X</translation>
    </message>
    <message>
        <source>X (%1)</source>
        <translation>X (%1)</translation>
    </message>
    <message>
        <source>Y</source>
        <translation>Y</translation>
    </message>
    <message>
        <source>Y (%1)</source>
        <translation>Y (%1)</translation>
    </message>
</context>
<context>
    <name>ui::ZnPanel</name>
    <message>
        <source>Ziegler–Nichols P</source>
        <translation>Ziegler–Nichols P</translation>
    </message>
    <message>
        <source>Ziegler–Nichols PI</source>
        <translation>Ziegler–Nichols PI</translation>
    </message>
    <message>
        <source>Ziegler–Nichols PID</source>
        <translation>Ziegler–Nichols PID</translation>
    </message>
    <message>
        <source>Tyreus–Luyben PI</source>
        <translation>Tyreus–Luyben PI</translation>
    </message>
    <message>
        <source>Tyreus–Luyben PID</source>
        <translation>Tyreus–Luyben PID</translation>
    </message>
    <message>
        <source>Pessen integral rule PID</source>
        <translation>Pessen 积分法则 PID</translation>
    </message>
    <message>
        <source>Z-N &quot;some overshoot&quot; PID</source>
        <translation>Z-N“少量超调” PID</translation>
    </message>
    <message>
        <source>Z-N &quot;no overshoot&quot; PID</source>
        <translation>Z-N“无超调” PID</translation>
    </message>
    <message>
        <source>seed 002 Table 1 (Ziegler &amp; Nichols 1942)</source>
        <translation>文献 002 表 1（Ziegler &amp; Nichols 1942）</translation>
    </message>
    <message>
        <source>Tyreus &amp; Luyben 1992, Ind. Eng. Chem. Res. 31:2625</source>
        <translation>Tyreus &amp; Luyben 1992, Ind. Eng. Chem. Res. 31:2625</translation>
    </message>
    <message>
        <source>Pessen 1994, J. Dyn. Syst. Meas. Control 116:553</source>
        <translation>Pessen 1994, J. Dyn. Syst. Meas. Control 116:553</translation>
    </message>
    <message>
        <source>Z-N variant as tabulated by Microstar Laboratories</source>
        <translation>Microstar Laboratories 列表中的 Z-N 变体</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Ultimate gain (P only, Kp raised)</source>
        <translation>临界增益法（纯比例，逐步增大 Kp）</translation>
    </message>
    <message>
        <source>Relay (Åström–Hägglund)</source>
        <translation>继电法（Åström–Hägglund）</translation>
    </message>
    <message>
        <source>Method</source>
        <translation>方法</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Max excursion</source>
        <translation>最大偏移</translation>
    </message>
    <message>
        <source>Max following error</source>
        <translation>最大跟随误差</translation>
    </message>
    <message>
        <source>Max duration</source>
        <translation>最长时间</translation>
    </message>
    <message>
        <source>Trial step</source>
        <translation>试验阶跃</translation>
    </message>
    <message>
        <source>First Kp</source>
        <translation>初始 Kp</translation>
    </message>
    <message>
        <source>Largest Kp</source>
        <translation>最大 Kp</translation>
    </message>
    <message>
        <source>Refine to the phase crossover</source>
        <translation>细化到相位穿越点</translation>
    </message>
    <message>
        <source>Short forced runs measure the loop at chosen frequencies until two points bracket −180°; without it only the classic describing-function estimate is given</source>
        <translation>在选定频率下做若干次短时强迫振荡试验测量回路，直到有两个点夹住 −180°；不勾选则只给出经典描述函数法的估计值</translation>
    </message>
    <message>
        <source>Amplitude d</source>
        <translation>继电幅值 d</translation>
    </message>
    <message>
        <source>Hysteresis ε</source>
        <translation>滞环 ε</translation>
    </message>
    <message>
        <source>no verification</source>
        <translation>不验证</translation>
    </message>
    <message>
        <source>Verify with</source>
        <translation>验证规则</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>开始</translation>
    </message>
    <message>
        <source>Abort</source>
        <translation>中止</translation>
    </message>
    <message>
        <source>Trials run inside 60 % of the envelope. Trial gains live only inside a test: the gains in force change when you press “Use these”.</source>
        <translation>试验在安全包络的 60 % 以内进行。试验增益只在测试中使用：按下“采用”后，生效的增益才会改变。</translation>
    </message>
    <message>
        <source>Rule</source>
        <translation>规则</translation>
    </message>
    <message>
        <source>Kp</source>
        <translation>Kp</translation>
    </message>
    <message>
        <source>Ki [1/s]</source>
        <translation>Ki [1/s]</translation>
    </message>
    <message>
        <source>Kd [s]</source>
        <translation>Kd [s]</translation>
    </message>
    <message>
        <source>kp</source>
        <translation>kp</translation>
    </message>
    <message>
        <source>ki / period</source>
        <translation>ki / 周期</translation>
    </message>
    <message>
        <source>kd / period</source>
        <translation>kd / 周期</translation>
    </message>
    <message>
        <source> µm</source>
        <translation> µm</translation>
    </message>
    <message>
        <source>Ku and Tu appear here once a method has run.</source>
        <translation>运行一种方法后，Ku 和 Tu 将显示在此处。</translation>
    </message>
    <message>
        <source>&lt;b&gt;Ku = %1, Tu = %2&lt;/b&gt; (%3 on %4, %5 runs)</source>
        <translation>&lt;b&gt;Ku = %1，Tu = %2&lt;/b&gt;（%4 上的%3，%5 次试验）</translation>
    </message>
    <message>
        <source>relay</source>
        <translation>继电法</translation>
    </message>
    <message>
        <source>ultimate gain</source>
        <translation>临界增益法</translation>
    </message>
    <message>
        <source>&lt;br&gt;Classic describing function: Ku = %1, Tu = %2 — %3</source>
        <translation>&lt;br&gt;经典描述函数法：Ku = %1，Tu = %2 — %3</translation>
    </message>
    <message>
        <source>refined above from the measured phase crossover</source>
        <translation>已根据实测相位穿越点在上方细化</translation>
    </message>
    <message>
        <source>not refined</source>
        <translation>未细化</translation>
    </message>
    <message>
        <source>, &lt;b&gt;never inside ±5 µm&lt;/b&gt;</source>
        <translation>，&lt;b&gt;从未进入 ±5 µm 范围&lt;/b&gt;</translation>
    </message>
    <message>
        <source>Use these</source>
        <translation>采用</translation>
    </message>
    <message>
        <source>Z-N %1: %2</source>
        <translation>Z-N %1：%2</translation>
    </message>
    <message>
        <source>, inside ±5 µm of the target from %1 ms</source>
        <translation>，自 %1 ms 起在目标 ±5 µm 以内</translation>
    </message>
    <message>
        <source>Source: %1</source>
        <translation>来源：%1</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>未测得</translation>
    </message>
    <message>
        <source>&lt;br&gt;Verification with %1: overshoot %2, %3</source>
        <translation>&lt;br&gt;用 %1 验证：超调量 %2，%3</translation>
    </message>
    <message>
        <source>&lt;br&gt;Verification with %1: &lt;b&gt;unstable&lt;/b&gt; (%2)</source>
        <translation>&lt;br&gt;用 %1 验证：&lt;b&gt;不稳定&lt;/b&gt;（%2）</translation>
    </message>
    <message>
        <source>&lt;br&gt;Verification with %1: &lt;b&gt;never comes to rest&lt;/b&gt;: a limit cycle of ±%2 µm every %3 remains (a still axis reads at most %4 µm peak to peak on its grating); overshoot %5</source>
        <translation>&lt;br&gt;用 %1 验证：&lt;b&gt;始终未静止&lt;/b&gt;：仍有 ±%2 µm、周期 %3 的极限环（静止的轴在光栅上的读数峰峰值至多 %4 µm）；超调量 %5</translation>
    </message>
    <message>
        <source>&lt;br&gt;Verification with %1: &lt;b&gt;never comes to rest&lt;/b&gt;: a limit cycle of ±%2 every %3 remains; overshoot %4</source>
        <translation>&lt;br&gt;用 %1 验证：&lt;b&gt;始终未静止&lt;/b&gt;：仍有 ±%2、周期 %3 的极限环；超调量 %4</translation>
    </message>
    <message>
        <source>&lt;br&gt;Verification with %1: &lt;b&gt;did not settle&lt;/b&gt; within 2 % of its step; overshoot %2</source>
        <translation>&lt;br&gt;用 %1 验证：&lt;b&gt;未稳定&lt;/b&gt;在阶跃的 2 % 以内；超调量 %2</translation>
    </message>
</context>
<context>
    <name>ui::report</name>
    <message>
        <source>Instrument: %1</source>
        <translation>仪器：%1</translation>
    </message>
    <message>
        <source>Reference: %1</source>
        <translation>测量基准：%1</translation>
    </message>
    <message>
        <source>Axis %1, %2 targets (mm): %3</source>
        <translation>%1 轴，%2 个目标位置 (mm)：%3</translation>
    </message>
    <message>
        <source>%1 cycles, %2</source>
        <translation>%1 次循环，%2</translation>
    </message>
    <message>
        <source>bidirectional (ISO 230-2 standard linear cycle)</source>
        <translation>双向（ISO 230-2 标准线性循环）</translation>
    </message>
    <message>
        <source>unidirectional (approached from below)</source>
        <translation>单向（从下方趋近）</translation>
    </message>
    <message>
        <source>Feed %1, overrun %2, dwell %3; settled within %4 for %5 (timeout %6)</source>
        <translation>进给速度 %1，越程 %2，停留 %3；在 %4 以内稳定 %5 后读数（超时 %6）</translation>
    </message>
    <message>
        <source>Readings: %1</source>
        <translation>读数文件：%1</translation>
    </message>
    <message>
        <source>Figure</source>
        <translation>指标</translation>
    </message>
    <message>
        <source>Before (µm)</source>
        <translation>补偿前 (µm)</translation>
    </message>
    <message>
        <source>After (µm)</source>
        <translation>补偿后 (µm)</translation>
    </message>
    <message>
        <source>Improvement</source>
        <translation>改善倍数</translation>
    </message>
    <message>
        <source>Value (µm)</source>
        <translation>数值 (µm)</translation>
    </message>
    <message>
        <source>Limit (µm)</source>
        <translation>限值 (µm)</translation>
    </message>
    <message>
        <source>Verdict</source>
        <translation>判定</translation>
    </message>
    <message>
        <source>pass</source>
        <translation>合格</translation>
    </message>
    <message>
        <source>FAIL</source>
        <translation>不合格</translation>
    </message>
    <message>
        <source>target (mm)</source>
        <translation>目标位置 (mm)</translation>
    </message>
    <message>
        <source>deviation (µm)</source>
        <translation>偏差 (µm)</translation>
    </message>
    <message>
        <source>mean ↑</source>
        <translation>平均值 ↑</translation>
    </message>
    <message>
        <source>mean ↓</source>
        <translation>平均值 ↓</translation>
    </message>
    <message>
        <source>mean ± 2s</source>
        <translation>平均值 ± 2s</translation>
    </message>
    <message>
        <source>readings ↑</source>
        <translation>读数 ↑</translation>
    </message>
    <message>
        <source>readings ↓</source>
        <translation>读数 ↓</translation>
    </message>
    <message>
        <source>BenchPilot accuracy report · %1 · %2</source>
        <translation>BenchPilot 精度报告 · %1 · %2</translation>
    </message>
    <message>
        <source>Figures before and after compensation (ISO 230-2:2014)</source>
        <translation>补偿前后的评定指标（ISO 230-2:2014）</translation>
    </message>
    <message>
        <source>Figures (ISO 230-2:2014)</source>
        <translation>评定指标（ISO 230-2:2014）</translation>
    </message>
    <message>
        <source>PASS: every figure judged is within its limit.</source>
        <translation>合格：所有参与评定的指标均在限值以内。</translation>
    </message>
    <message>
        <source>FAIL: a figure is beyond its limit.</source>
        <translation>不合格：有指标超出限值。</translation>
    </message>
    <message>
        <source>No tolerances were given: the figures are not judged.</source>
        <translation>未给出公差：不对指标进行评定。</translation>
    </message>
    <message>
        <source>Deviations: mean ± 2s per direction</source>
        <translation>偏差：各方向的平均值 ± 2s</translation>
    </message>
    <message>
        <source>Per target (µm)</source>
        <translation>各目标位置 (µm)</translation>
    </message>
    <message>
        <source>Before and after</source>
        <translation>补偿前后</translation>
    </message>
    <message>
        <source>mean deviation (µm)</source>
        <translation>平均偏差 (µm)</translation>
    </message>
    <message>
        <source>before</source>
        <translation>补偿前</translation>
    </message>
    <message>
        <source>after</source>
        <translation>补偿后</translation>
    </message>
    <message>
        <source>Compensation fit of the mean deviations (seed 002&apos;s method)</source>
        <translation>平均偏差的补偿拟合（文献 002 的方法）</translation>
    </message>
    <message>
        <source>order</source>
        <translation>阶数</translation>
    </message>
    <message>
        <source>SSE (µm²)</source>
        <translation>残差平方和 (µm²)</translation>
    </message>
    <message>
        <source>adjusted R²</source>
        <translation>调整后 R²</translation>
    </message>
    <message>
        <source>chosen</source>
        <translation>选用</translation>
    </message>
    <message>
        <source>not enough points</source>
        <translation>点数不足</translation>
    </message>
    <message>
        <source>e(x) = %1 µm, x in mm (order %2%3)</source>
        <translation>e(x) = %1 µm，x 单位为 mm（%2 阶%3）</translation>
    </message>
    <message>
        <source>, chosen by the operator</source>
        <translation>，由操作员选定</translation>
    </message>
    <message>
        <source>, chosen by adjusted R²</source>
        <translation>，按调整后 R² 选定</translation>
    </message>
    <message>
        <source>residual (µm)</source>
        <translation>残差 (µm)</translation>
    </message>
    <message>
        <source>mean deviation − fit</source>
        <translation>平均偏差 − 拟合值</translation>
    </message>
    <message>
        <source>a PDF needs a graphical application object; none exists in this program</source>
        <translation>生成 PDF 需要图形应用程序对象，而本程序中没有</translation>
    </message>
    <message>
        <source>— clockwise</source>
        <translation>— 顺时针</translation>
    </message>
    <message>
        <source>— counter-clockwise</source>
        <translation>— 逆时针</translation>
    </message>
    <message>
        <source>radius %1, deviation from the least-squares circle magnified %2×; dashed: the nominal circle</source>
        <translation>半径 %1，相对最小二乘圆的偏差放大 %2×；虚线：名义圆</translation>
    </message>
    <message>
        <source>Instrument: %1
Plane %2, centre (%3, %4), radius %5, feed %6, lead arc %7; %8 samples a revolution</source>
        <translation>仪器：%1
平面 %2，圆心（%3, %4），半径 %5，进给速度 %6，引入弧 %7；每周 %8 个采样点</translation>
    </message>
    <message>
        <source>Figures (ISO 230-4, µm)</source>
        <translation>评定指标（ISO 230-4，µm）</translation>
    </message>
    <message>
        <source>figure</source>
        <translation>指标</translation>
    </message>
    <message>
        <source>value (µm)</source>
        <translation>数值 (µm)</translation>
    </message>
    <message>
        <source>limit (µm)</source>
        <translation>限值 (µm)</translation>
    </message>
    <message>
        <source>verdict</source>
        <translation>判定</translation>
    </message>
    <message>
        <source>clockwise</source>
        <translation>顺时针</translation>
    </message>
    <message>
        <source>counter-clockwise</source>
        <translation>逆时针</translation>
    </message>
    <message>
        <source>G circular deviation, %1</source>
        <translation>G 圆偏差，%1</translation>
    </message>
    <message>
        <source>radial deviation, %1: min … max</source>
        <translation>径向偏差，%1：最小 … 最大</translation>
    </message>
    <message>
        <source>G(b) bidirectional circular deviation</source>
        <translation>G(b) 双向圆偏差</translation>
    </message>
    <message>
        <source>H circular hysteresis</source>
        <translation>H 圆滞后</translation>
    </message>
    <message>
        <source>BenchPilot circular test · %1 · %2</source>
        <translation>BenchPilot 圆测试 · %1 · %2</translation>
    </message>
    <message>
        <source>cannot write %1</source>
        <translation>无法写入 %1</translation>
    </message>
    <message>
        <source>value</source>
        <translation>值</translation>
    </message>
    <message>
        <source>scale X (ppm)</source>
        <translation>X 比例误差 (ppm)</translation>
    </message>
    <message>
        <source>scale Y (ppm)</source>
        <translation>Y 比例误差 (ppm)</translation>
    </message>
    <message>
        <source>squareness (µrad)</source>
        <translation>垂直度 (µrad)</translation>
    </message>
    <message>
        <source>straightness X (µm)</source>
        <translation>X 直线度 (µm)</translation>
    </message>
    <message>
        <source>straightness Y (µm)</source>
        <translation>Y 直线度 (µm)</translation>
    </message>
    <message>
        <source>error RMS (µm)</source>
        <translation>误差均方根 (µm)</translation>
    </message>
    <message>
        <source>error max (µm)</source>
        <translation>最大误差 (µm)</translation>
    </message>
    <message>
        <source>residual RMS (µm)</source>
        <translation>残差均方根 (µm)</translation>
    </message>
    <message>
        <source>%1 × %2 nodes every %3 × %4 on a grid plate of %5 pitch, each row approached from below</source>
        <translation>%1 × %2 个节点，间距 %3 × %4，网格板间距 %5，每行均从下方趋近</translation>
    </message>
    <message>
        <source>Plate placement fitted out: offset (%1, %2) µm, rotation %3 µrad</source>
        <translation>已拟合去除网格板摆放：偏移 (%1, %2) µm，旋转 %3 µrad</translation>
    </message>
    <message>
        <source>The camera&apos;s pixel size scales only each dot&apos;s small offset from the image centre: the scales are those of the plate&apos;s certified pitch, which a pixel size calibrated on this same stage cannot reveal.</source>
        <translation>相机像素尺寸只影响每个圆点相对图像中心的微小偏移：比例误差以网格板的认证间距为准；用同一平台标定的像素尺寸无法揭示平台自身的比例误差。</translation>
    </message>
    <message>
        <source>Figures (ISO 230-1 least-squares reference lines)</source>
        <translation>指标（ISO 230-1 最小二乘参考线）</translation>
    </message>
    <message>
        <source>Error map</source>
        <translation>误差图</translation>
    </message>
    <message>
        <source>Before: compensation off</source>
        <translation>补偿前：补偿关闭</translation>
    </message>
    <message>
        <source>After: the 2D table enabled</source>
        <translation>补偿后：已启用二维补偿表</translation>
    </message>
    <message>
        <source>Arrows: each node&apos;s error with the plate&apos;s placement removed, magnified %1×; colour: the error&apos;s length, one scale for every map on the page.</source>
        <translation>箭头：去除网格板摆放后每个节点的误差，放大 %1 倍；颜色：误差长度，本页所有图使用同一色标。</translation>
    </message>
    <message>
        <source>BenchPilot grid map · %1 · %2</source>
        <translation>BenchPilot 网格图 · %1 · %2</translation>
    </message>
    <message>
        <source>reversal max (µm)</source>
        <translation>反向差最大值 (µm)</translation>
    </message>
    <message>
        <source>mean reversal X (µm)</source>
        <translation>X 平均反向差 (µm)</translation>
    </message>
    <message>
        <source>mean reversal Y (µm)</source>
        <translation>Y 平均反向差 (µm)</translation>
    </message>
    <message>
        <source>%1 × %2 nodes every %3 × %4 on a grid plate of %5 pitch, read both ways: each row approached from below, then every node again in reverse order from above. The map and its figures are the mean of the two directions.</source>
        <translation>%1 × %2 个节点，间距 %3 × %4，网格板间距 %5，双向读取：每行先从下方趋近，再按相反顺序从上方趋近每个节点。网格图及其指标为两个方向的平均值。</translation>
    </message>
    <message>
        <source>Reversal map</source>
        <translation>反向差图</translation>
    </message>
    <message>
        <source>%1 · %2</source>
        <translation>%1 · %2</translation>
    </message>
    <message>
        <source>read one way: no reversal</source>
        <translation>单向读取：无反向差</translation>
    </message>
    <message>
        <source>Arrows: each node&apos;s reversal (forward − reverse), magnified %1×; colour: its length. Its mean along X and along Y is the axes&apos; lost motion, which a 2D table cannot correct.</source>
        <translation>箭头：每个节点的反向差（正向 − 反向），放大 %1 倍；颜色：其长度。其沿 X 和沿 Y 的平均值即各轴的空程，二维补偿表无法校正。</translation>
    </message>
</context>
<context>
    <name>ui::words::AccuracyBenchWords</name>
    <message>
        <source>must be a number (not NaN or infinite)</source>
        <translation>必须是数字（不能是 NaN 或无穷大）</translation>
    </message>
    <message>
        <source>is %1, below the least allowed %2</source>
        <translation>为 %1，低于允许的最小值 %2</translation>
    </message>
    <message>
        <source>is %1, above the most allowed %2</source>
        <translation>为 %1，高于允许的最大值 %2</translation>
    </message>
    <message>
        <source>must be above 0 (is %1)</source>
        <translation>必须大于 0（当前为 %1）</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not an axis name: one capital letter, such as X</source>
        <translation>“%1”不是轴名：轴名是一个大写字母，例如 X</translation>
    </message>
    <message>
        <source>no targets: give a list of targets or a start, end and count</source>
        <translation>没有目标位置：请给出目标位置列表，或起点、终点和个数</translation>
    </message>
    <message>
        <source>give either a list of targets or a grid, not both</source>
        <translation>请给出目标位置列表或网格之一，不能同时给出</translation>
    </message>
    <message>
        <source>%1 targets: a positioning test needs at least %2</source>
        <translation>%1 个目标位置：定位测试至少需要 %2 个</translation>
    </message>
    <message>
        <source>%1 targets: ISO 230-2 recommends at least %2</source>
        <translation>%1 个目标位置：ISO 230-2 建议至少 %2 个</translation>
    </message>
    <message>
        <source>target %1 does not come after %2: targets must increase</source>
        <translation>目标位置 %1 不大于 %2：目标位置必须递增</translation>
    </message>
    <message>
        <source>target %1 of axis %2 is below the soft limit %3</source>
        <translation>%2 轴的目标位置 %1 低于软限位 %3</translation>
    </message>
    <message>
        <source>target %1 is below the soft limit %2</source>
        <translation>目标位置 %1 低于软限位 %2</translation>
    </message>
    <message>
        <source>target %1 of axis %2 is above the soft limit %3</source>
        <translation>%2 轴的目标位置 %1 高于软限位 %3</translation>
    </message>
    <message>
        <source>target %1 is above the soft limit %2</source>
        <translation>目标位置 %1 高于软限位 %2</translation>
    </message>
    <message>
        <source>the grid ends at %1, not after its start %2</source>
        <translation>网格终点 %1 不在起点 %2 之后</translation>
    </message>
    <message>
        <source>targets %1 apart are too close: at least %2</source>
        <translation>目标位置间距 %1 太小：至少为 %2</translation>
    </message>
    <message>
        <source>no overrun: the drive reverses at the end targets, so their readings include the reversal</source>
        <translation>没有越程：驱动在两端目标位置处换向，因此这些读数包含了换向误差</translation>
    </message>
    <message>
        <source>the overrun takes axis %1 to %2, below the soft limit %3</source>
        <translation>越程使 %1 轴到达 %2，低于软限位 %3</translation>
    </message>
    <message>
        <source>the overrun goes to %1, below the soft limit %2</source>
        <translation>越程到达 %1，低于软限位 %2</translation>
    </message>
    <message>
        <source>the overrun takes axis %1 to %2, above the soft limit %3</source>
        <translation>越程使 %1 轴到达 %2，高于软限位 %3</translation>
    </message>
    <message>
        <source>the overrun goes to %1, above the soft limit %2</source>
        <translation>越程到达 %1，高于软限位 %2</translation>
    </message>
    <message>
        <source>%1 cycles at %2 %3: at least %4 are needed to see a spread</source>
        <translation>%2 %3 处 %1 次循环：至少需要 %4 次才能看出分散</translation>
    </message>
    <message>
        <source>%1 cycles: at least %2 are needed to see a spread</source>
        <translation>%1 次循环：至少需要 %2 次才能看出分散</translation>
    </message>
    <message>
        <source>%1 cycles: ISO 230-2 recommends %2</source>
        <translation>%1 次循环：ISO 230-2 建议 %2 次</translation>
    </message>
    <message>
        <source>the settle timeout %1 is shorter than its window %2</source>
        <translation>稳定超时 %1 短于其稳定窗口 %2</translation>
    </message>
    <message>
        <source>a second reading at %1 %2 in cycle %3 (the first is reading %4)</source>
        <translation>第 %3 次循环中在 %1 %2 处有第二个读数（第一个是读数 %4）</translation>
    </message>
    <message>
        <source>no %1 readings at %2, though other targets have them</source>
        <translation>%2 处没有%1读数，但其他目标位置有</translation>
    </message>
    <message>
        <source>%1 readings at %2 %3, where the others have %4</source>
        <translation>%2 %3 处有 %1 个读数，而其他位置有 %4 个</translation>
    </message>
    <message>
        <source>the table&apos;s row for %1 lacks a mean or a standard deviation</source>
        <translation>表中 %1 一行缺少平均值或标准差</translation>
    </message>
    <message>
        <source>%1 readings, where the test has %2</source>
        <translation>%1 个读数，而测试应有 %2 个</translation>
    </message>
    <message>
        <source>a reading at %1 %2 in cycle %3, which the test does not have</source>
        <translation>第 %3 次循环在 %1 %2 处有读数，但测试中没有这一点</translation>
    </message>
    <message>
        <source>no reading at %1 %2 in cycle %3</source>
        <translation>第 %3 次循环在 %1 %2 处没有读数</translation>
    </message>
    <message>
        <source>this target is %1 off the line through the first and last (at most %2)</source>
        <translation>该目标位置偏离首末两点连线 %1（最多允许 %2）</translation>
    </message>
    <message>
        <source>reading for target %1, but the line has %2 targets</source>
        <translation>读数对应目标位置 %1，但该直线只有 %2 个目标位置</translation>
    </message>
    <message>
        <source>%1 does not move along this line: it is not evaluated</source>
        <translation>%1 轴沿该直线不运动：不予评定</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a plane: two different axis letters, such as XY</source>
        <translation>“%1”不是平面：应为两个不同的轴字母，例如 XY</translation>
    </message>
    <message>
        <source>the circle reaches %1 = %2, below the soft limit %3</source>
        <translation>圆到达 %1 = %2，低于软限位 %3</translation>
    </message>
    <message>
        <source>the circle reaches %1 = %2, above the soft limit %3</source>
        <translation>圆到达 %1 = %2，高于软限位 %3</translation>
    </message>
    <message>
        <source>choose clockwise, counter-clockwise or both</source>
        <translation>请选择顺时针、逆时针或两者</translation>
    </message>
    <message>
        <source>no circle was sampled</source>
        <translation>没有采样任何圆</translation>
    </message>
    <message>
        <source>two %1 runs: one of each direction</source>
        <translation>两次%1运行：每个方向只能一次</translation>
    </message>
    <message>
        <source>%1 samples of a circle: at least %2</source>
        <translation>圆上只有 %1 个采样点：至少需要 %2 个</translation>
    </message>
    <message>
        <source>the samples leave a gap of %1 in the revolution (at most %2)</source>
        <translation>采样点在一周中留有 %1 的空缺（最多允许 %2）</translation>
    </message>
    <message>
        <source>the %1 samples do not lie on a circle</source>
        <translation>%1采样点不在一个圆上</translation>
    </message>
    <message>
        <source>%1 is written as %2, but the file&apos;s own table gives %3</source>
        <translation>%1 写的是 %2，但文件自身的表格给出 %3</translation>
    </message>
    <message>
        <source>A run is in progress: pause or abort it first.</source>
        <translation>正在运行：请先暂停或中止。</translation>
    </message>
    <message>
        <source>The instrument is not connected.</source>
        <translation>仪器未连接。</translation>
    </message>
    <message>
        <source>The instrument has no axis %1 for this test.</source>
        <translation>仪器没有本测试所需的 %1 轴。</translation>
    </message>
    <message>
        <source>The test&apos;s axes are not homed: home them first.</source>
        <translation>测试所用的轴尚未回零：请先回零。</translation>
    </message>
    <message>
        <source>Axis %1 is not homed: home it first.</source>
        <translation>%1 轴尚未回零：请先回零。</translation>
    </message>
    <message>
        <source>E-stop is active: the run stopped; reset the E-stop and resume.</source>
        <translation>急停已触发：运行已停止；请复位急停后继续。</translation>
    </message>
    <message>
        <source>Choose where the readings come from.</source>
        <translation>请选择读数来源。</translation>
    </message>
    <message>
        <source>The %1 reads %2 axis at a time; this test reads %3.</source>
        <translation>%1每次只能读取 %2 个轴；本测试需读取 %3 个。</translation>
    </message>
    <message>
        <source>The gauge on %1 reads one axis; this test reads two.</source>
        <translation>%1 上的测头只能读取一个轴；本测试需读取两个。</translation>
    </message>
    <message>
        <source>Cannot use the folder %1: cannot create it.</source>
        <translation>无法使用文件夹 %1：无法创建该文件夹。</translation>
    </message>
    <message>
        <source>%1 holds the run log of another test (%2): choose another folder, or start afresh to keep it aside.</source>
        <translation>%1 中是另一项测试（%2）的运行日志：请选择其他文件夹，或重新开始（旧日志将另存）。</translation>
    </message>
    <message>
        <source>The run log %1 cannot be continued (line %2): %3.</source>
        <translation>运行日志 %1 无法续写（第 %2 行）：%3。</translation>
    </message>
    <message>
        <source>Cannot write the run log %1: cannot keep the old log aside as %2.</source>
        <translation>无法写入运行日志 %1：无法将旧日志另存为 %2。</translation>
    </message>
    <message>
        <source>Cannot write the run log %1: %2. The run stopped; no reading was lost.</source>
        <translation>无法写入运行日志 %1：%2。运行已停止；没有丢失任何读数。</translation>
    </message>
    <message>
        <source>The instrument refused the move: %1</source>
        <translation>仪器拒绝了该移动：%1</translation>
    </message>
    <message>
        <source>The link to the instrument was lost: the run stopped. Reconnect and resume: it goes on at the next reading.</source>
        <translation>与仪器的连接中断：运行已停止。请重新连接后继续：将从下一个读数接着运行。</translation>
    </message>
    <message>
        <source>The run was aborted. Resume goes on at the next reading.</source>
        <translation>运行已中止。按“继续”将从下一个读数接着运行。</translation>
    </message>
    <message>
        <source>Axis %1 stopped (%2): %3. The run stopped.</source>
        <translation>%1 轴已停止（%2）：%3。运行已停止。</translation>
    </message>
    <message>
        <source>No position reading from the instrument: %1</source>
        <translation>未能从仪器读到位置：%1</translation>
    </message>
    <message>
        <source>No position reading from the instrument: its status has no axis %1.</source>
        <translation>未能从仪器读到位置：其状态中没有 %1 轴。</translation>
    </message>
    <message>
        <source>The reading has %1 values where the test reads %2 axes: the run stopped.</source>
        <translation>读数有 %1 个值，而测试读取 %2 个轴：运行已停止。</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>Define or open a test first.</source>
        <translation>请先定义或打开一项测试。</translation>
    </message>
    <message>
        <source>Every reading of this run is taken.</source>
        <translation>本次运行的所有读数均已采集。</translation>
    </message>
    <message>
        <source>A circular test runs as a circle, not as stops.</source>
        <translation>圆测试按整圆运行，而不是逐个测点运行。</translation>
    </message>
    <message>
        <source>The run took far longer than its estimate and was aborted.</source>
        <translation>运行用时远超预估，已被中止。</translation>
    </message>
    <message>
        <source>The circle&apos;s path was aborted.</source>
        <translation>圆的路径已中止。</translation>
    </message>
    <message>
        <source>The circle&apos;s path was aborted: %1</source>
        <translation>圆的路径已中止：%1</translation>
    </message>
    <message>
        <source>the header has no %1 column</source>
        <translation>表头中没有 %1 列</translation>
    </message>
    <message>
        <source>cannot read the unit of column %1: use one of %2</source>
        <translation>无法识别 %1 列的单位：请使用 %2 之一</translation>
    </message>
    <message>
        <source>a second column for the same quantity: %1</source>
        <translation>同一物理量出现了第二列：%1</translation>
    </message>
    <message>
        <source>the file has no readings</source>
        <translation>文件中没有读数</translation>
    </message>
    <message>
        <source>%1 cells where the header has %2</source>
        <translation>有 %1 个单元格，而表头有 %2 列</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a number</source>
        <translation>“%1”不是数字</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a direction: up or down</source>
        <translation>“%1”不是方向：应为 up 或 down</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a cycle: a whole number from 1</source>
        <translation>“%1”不是循环序号：应为从 1 开始的整数</translation>
    </message>
    <message>
        <source>the export has %1 readings, where the run&apos;s sequence has %2 stops</source>
        <translation>导出文件有 %1 个读数，而运行序列有 %2 个测点</translation>
    </message>
    <message>
        <source>reading %1 was taken %2, where the run&apos;s stop %1 (at %3) was approached %4</source>
        <translation>读数 %1 为%2趋近，而运行的第 %1 个测点（%3 处）为%4趋近</translation>
    </message>
    <message>
        <source>reading %1 is for target %2, where the run&apos;s stop %1 is at %3</source>
        <translation>读数 %1 对应目标位置 %2，而运行的第 %1 个测点位于 %3</translation>
    </message>
    <message>
        <source>index &quot;%1&quot;: the sequence&apos;s rows are numbered from 1 in order (expected %2)</source>
        <translation>序号“%1”：序列各行应从 1 起按顺序编号（应为 %2）</translation>
    </message>
    <message>
        <source>must hold numbers (mm)</source>
        <translation>必须是数值（单位 mm）</translation>
    </message>
    <message>
        <source>must hold one position per axis read, one or two (mm)</source>
        <translation>必须为所读的每个轴给出一个位置，共一个或两个（单位 mm）</translation>
    </message>
    <message>
        <source>is %1 where the run&apos;s next stop is %2: a log&apos;s stops come in order, each once</source>
        <translation>为 %1，而运行的下一个测点是 %2：日志中的测点须按顺序出现，且每个只出现一次</translation>
    </message>
    <message>
        <source>must hold as many positions as target_mm</source>
        <translation>位置个数必须与 target_mm 相同</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <source>not valid JSON: %1</source>
        <translation>不是有效的 JSON：%1</translation>
    </message>
    <message>
        <source>a quoted field is not closed</source>
        <translation>带引号的字段没有闭合</translation>
    </message>
    <message>
        <source>text after a closing quote</source>
        <translation>闭合引号之后还有文字</translation>
    </message>
    <message>
        <source>the file is separated by semicolons; BenchPilot reads commas and &apos;.&apos; as the decimal point</source>
        <translation>文件以分号分隔；BenchPilot 读取逗号分隔、以“.”为小数点的文件</translation>
    </message>
    <message>
        <source>%1 points: a fit needs at least %2 different positions</source>
        <translation>%1 个点：拟合至少需要 %2 个不同位置</translation>
    </message>
    <message>
        <source>order %1: choose %2 to %3</source>
        <translation>阶数 %1：请选择 %2 到 %3</translation>
    </message>
    <message>
        <source>order %1 needs at least %2 points; there are %3</source>
        <translation>%1 阶至少需要 %2 个点；现有 %3 个</translation>
    </message>
    <message>
        <source>the polynomial has no coefficients</source>
        <translation>多项式没有系数</translation>
    </message>
    <message>
        <source>%1 coefficients: at most %2 (order 5)</source>
        <translation>%1 个系数：最多 %2 个（5 阶）</translation>
    </message>
    <message>
        <source>the range %1 to %2 is shorter than %3</source>
        <translation>范围 %1 到 %2 短于 %3</translation>
    </message>
    <message>
        <source>the curve reaches %1 at %2, beyond ±%3</source>
        <translation>曲线在 %2 处达到 %1，超出 ±%3</translation>
    </message>
    <message>
        <source>the curve&apos;s slope is %1 µm/mm at %2, beyond %3</source>
        <translation>曲线在 %2 处的斜率为 %1 µm/mm，超出 %3</translation>
    </message>
    <message>
        <source>%1 table points: at least %2</source>
        <translation>%1 个表格点：至少需要 %2 个</translation>
    </message>
    <message>
        <source>%1 table points: a device keeps at most %2</source>
        <translation>%1 个表格点：设备最多保存 %2 个</translation>
    </message>
    <message>
        <source>nominal %1 does not come after %2</source>
        <translation>名义位置 %1 不大于 %2</translation>
    </message>
    <message>
        <source>nominals %1 and %2 are closer than %3</source>
        <translation>名义位置 %1 与 %2 相距小于 %3</translation>
    </message>
    <message>
        <source>a backlash of %1 beside per-direction columns: put it in the columns</source>
        <translation>已有分方向的列，又给出反向间隙 %1：请把它并入各列</translation>
    </message>
    <message>
        <source>%1 values on a line where LinuxCNC expects three (nominal, forward, reverse); LinuxCNC would stop reading here</source>
        <translation>一行有 %1 个数，而 LinuxCNC 要求三个（名义、正向、反向）；LinuxCNC 读到这里会停止</translation>
    </message>
    <message>
        <source>axis %1 cannot carry a compensation</source>
        <translation>%1 轴不支持补偿</translation>
    </message>
    <message>
        <source>this instrument keeps no compensation of its own</source>
        <translation>该仪器自身不保存补偿</translation>
    </message>
    <message>
        <source>the compensation cannot be applied (%1): %2</source>
        <translation>无法应用该补偿（%1）：%2</translation>
    </message>
    <message>
        <source>the device answered COMP_UPLOAD with something unreadable</source>
        <translation>设备对 COMP_UPLOAD 的应答无法解读</translation>
    </message>
    <message>
        <source>the device took every part of the compensation but did not install it</source>
        <translation>设备接收了补偿的全部数据，但没有安装</translation>
    </message>
    <message>
        <source>the device answered COMP_GET with something unreadable</source>
        <translation>设备对 COMP_GET 的应答无法解读</translation>
    </message>
    <message>
        <source>The instrument refused: %1</source>
        <translation>仪器拒绝：%1</translation>
    </message>
    <message>
        <source>The instrument holds no compensation for axis %1.</source>
        <translation>仪器中没有 %1 轴的补偿。</translation>
    </message>
    <message>
        <source>The gauge on %1 answered &quot;%2&quot;, which is not a reading such as +012.3456 mm.</source>
        <translation>%1 上的测头应答“%2”，这不是形如 +012.3456 mm 的读数。</translation>
    </message>
    <message>
        <source>The gauge on %1 answered &quot;%2&quot; in a unit BenchPilot does not read (%3); it reads mm, µm and in.</source>
        <translation>%1 上的测头应答“%2”，其单位（%3）BenchPilot 无法识别；可识别的单位为 mm、µm 和 in。</translation>
    </message>
    <message>
        <source>The gauge on %1 did not answer within %2, asked twice.</source>
        <translation>%1 上的测头在 %2 内无应答（已询问两次）。</translation>
    </message>
    <message>
        <source>The gauge did not answer.</source>
        <translation>测头无应答。</translation>
    </message>
    <message>
        <source>Cannot open the gauge&apos;s port %1: %2</source>
        <translation>无法打开测头的端口 %1：%2</translation>
    </message>
    <message>
        <source>The gauge&apos;s port %1 went away: %2</source>
        <translation>测头的端口 %1 已断开：%2</translation>
    </message>
    <message>
        <source>The gauge on %1 is still answering the last request.</source>
        <translation>%1 上的测头仍在应答上一个请求。</translation>
    </message>
    <message>
        <source>The gauge on %1 has no port to talk through.</source>
        <translation>%1 上的测头没有可用于通信的端口。</translation>
    </message>
    <message>
        <source>The gauge&apos;s port %1 is not open.</source>
        <translation>测头的端口 %1 未打开。</translation>
    </message>
    <message>
        <source>readback</source>
        <translation>位置反馈</translation>
    </message>
    <message>
        <source>the stage&apos;s grating (readback)</source>
        <translation>载物台的光栅尺（位置反馈）</translation>
    </message>
    <message>
        <source>the analyzer&apos;s encoder (readback)</source>
        <translation>分析仪的编码器（位置反馈）</translation>
    </message>
    <message>
        <source>gauge on %1</source>
        <translation>%1 上的测头</translation>
    </message>
    <message>
        <source>manual entry</source>
        <translation>手动输入</translation>
    </message>
    <message>
        <source>laser interferometer (imported after the run)</source>
        <translation>激光干涉仪（运行后导入）</translation>
    </message>
    <message>
        <source>gauge</source>
        <translation>测头</translation>
    </message>
    <message>
        <source>interferometer</source>
        <translation>干涉仪</translation>
    </message>
    <message>
        <source>upload compensation</source>
        <translation>上传补偿</translation>
    </message>
    <message>
        <source>read compensation</source>
        <translation>读取补偿</translation>
    </message>
    <message>
        <source>enable compensation</source>
        <translation>启用补偿</translation>
    </message>
    <message>
        <source>disable compensation</source>
        <translation>停用补偿</translation>
    </message>
    <message>
        <source>as recorded: %1</source>
        <translation>按记录：%1</translation>
    </message>
    <message>
        <source>the sequence has %1 stops, where the test &quot;%3&quot; makes %2: it is the run of another test</source>
        <translation>序列有 %1 个测点，而测试“%3”有 %2 个：这是另一项测试的运行序列</translation>
    </message>
    <message>
        <source>the sequence&apos;s stop %1 is at %2, approached %3 in cycle %4, where the test &quot;%8&quot; goes to %5, approached %6 in cycle %7: it is the run of another test</source>
        <translation>序列的第 %1 个测点位于 %2，在第 %4 个循环中%3趋近，而测试“%8”在第 %7 个循环中%6趋近 %5：这是另一项测试的运行序列</translation>
    </message>
    <message>
        <source>camera %1 reading the glass scale along %2</source>
        <translation>相机 %1 读取沿 %2 轴的玻璃线纹尺</translation>
    </message>
    <message>
        <source>camera %1 reading the grid plate&apos;s dots</source>
        <translation>相机 %1 读取网格板的圆点</translation>
    </message>
    <message>
        <source>camera</source>
        <translation>相机</translation>
    </message>
</context>
<context>
    <name>ui::words::AccuracyWords</name>
    <message>
        <source>must be a number (not NaN or infinite)</source>
        <comment>accuracy.value_not_finite</comment>
        <translation>必须是数字（不能是 NaN 或无穷大）</translation>
    </message>
    <message>
        <source>is %1, below the least allowed %2</source>
        <comment>accuracy.value_below</comment>
        <translation>为 %1，低于允许的最小值 %2</translation>
    </message>
    <message>
        <source>is %1, above the most allowed %2</source>
        <comment>accuracy.value_above</comment>
        <translation>为 %1，高于允许的最大值 %2</translation>
    </message>
    <message>
        <source>must be above 0 (is %1)</source>
        <comment>accuracy.value_not_positive</comment>
        <translation>必须大于 0（当前为 %1）</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not an axis name: one capital letter, such as X</source>
        <comment>accuracy.axis_name_invalid</comment>
        <translation>“%1”不是轴名：轴名是一个大写字母，例如 X</translation>
    </message>
    <message>
        <source>no targets: give a list of targets or a start, end and count</source>
        <comment>accuracy.no_targets</comment>
        <translation>没有目标位置：请给出目标位置列表，或起点、终点和个数</translation>
    </message>
    <message>
        <source>give either a list of targets or a grid, not both</source>
        <comment>accuracy.targets_and_grid</comment>
        <translation>请给出目标位置列表或网格之一，不能同时给出</translation>
    </message>
    <message>
        <source>%1 targets: a positioning test needs at least %2</source>
        <comment>accuracy.too_few_targets</comment>
        <translation>%1 个目标位置：定位测试至少需要 %2 个</translation>
    </message>
    <message>
        <source>%1 targets: ISO 230-2 recommends at least %2</source>
        <comment>accuracy.fewer_targets_than_iso</comment>
        <translation>%1 个目标位置：ISO 230-2 建议至少 %2 个</translation>
    </message>
    <message>
        <source>target %1 does not come after %2: targets must increase</source>
        <comment>accuracy.targets_not_increasing</comment>
        <translation>目标位置 %1 不大于 %2：目标位置必须递增</translation>
    </message>
    <message>
        <source>target %1 is below the soft limit %2</source>
        <comment>accuracy.target_below_limit</comment>
        <translation>目标位置 %1 低于软限位 %2</translation>
    </message>
    <message>
        <source>target %1 is above the soft limit %2</source>
        <comment>accuracy.target_above_limit</comment>
        <translation>目标位置 %1 高于软限位 %2</translation>
    </message>
    <message>
        <source>the grid ends at %1, not after its start %2</source>
        <comment>accuracy.grid_end_not_after_start</comment>
        <translation>网格终点 %1 不在起点 %2 之后</translation>
    </message>
    <message>
        <source>targets %1 apart are too close: at least %2</source>
        <comment>accuracy.grid_spacing_too_small</comment>
        <translation>目标位置间距 %1 太小：至少为 %2</translation>
    </message>
    <message>
        <source>no overrun: the drive reverses at the end targets, so their readings include the reversal</source>
        <comment>accuracy.no_overrun</comment>
        <translation>没有越程：驱动在两端目标位置处换向，因此这些读数包含了换向误差</translation>
    </message>
    <message>
        <source>the overrun goes to %1, below the soft limit %2</source>
        <comment>accuracy.overrun_below_limit</comment>
        <translation>越程到达 %1，低于软限位 %2</translation>
    </message>
    <message>
        <source>the overrun goes to %1, above the soft limit %2</source>
        <comment>accuracy.overrun_above_limit</comment>
        <translation>越程到达 %1，高于软限位 %2</translation>
    </message>
    <message>
        <source>%1 cycles: at least %2 are needed to see a spread</source>
        <comment>accuracy.too_few_cycles</comment>
        <translation>%1 次循环：至少需要 %2 次才能看出分散</translation>
    </message>
    <message>
        <source>%1 cycles: ISO 230-2 recommends %2</source>
        <comment>accuracy.fewer_cycles_than_iso</comment>
        <translation>%1 次循环：ISO 230-2 建议 %2 次</translation>
    </message>
    <message>
        <source>the settle timeout %1 is shorter than its window %2</source>
        <comment>accuracy.settle_timeout_below_window</comment>
        <translation>稳定超时 %1 短于其稳定窗口 %2</translation>
    </message>
    <message>
        <source>a second reading at %1 %2 in cycle %3 (the first is reading %4)</source>
        <comment>accuracy.duplicate_reading</comment>
        <translation>第 %3 次循环中在 %1 %2 处有第二个读数（第一个是读数 %4）</translation>
    </message>
    <message>
        <source>no %1 readings at %2, though other targets have them</source>
        <comment>accuracy.direction_missing</comment>
        <translation>%2 处没有%1读数，但其他目标位置有</translation>
    </message>
    <message>
        <source>%1 readings at %2 %3, where the others have %4</source>
        <comment>accuracy.cycle_counts_differ</comment>
        <translation>%2 %3 处有 %1 个读数，而其他位置有 %4 个</translation>
    </message>
    <message>
        <source>the table&apos;s row for %1 lacks a mean or a standard deviation</source>
        <comment>accuracy.statistics_incomplete</comment>
        <translation>表中 %1 一行缺少平均值或标准差</translation>
    </message>
    <message>
        <source>%1 readings, where the test has %2</source>
        <comment>accuracy.reading_count_wrong</comment>
        <translation>%1 个读数，而测试应有 %2 个</translation>
    </message>
    <message>
        <source>a reading at %1 %2 in cycle %3, which the test does not have</source>
        <comment>accuracy.reading_not_in_plan</comment>
        <translation>第 %3 次循环在 %1 %2 处有读数，但测试中没有这一点</translation>
    </message>
    <message>
        <source>no reading at %1 %2 in cycle %3</source>
        <comment>accuracy.reading_missing</comment>
        <translation>第 %3 次循环在 %1 %2 处没有读数</translation>
    </message>
    <message>
        <source>this target is %1 off the line through the first and last (at most %2)</source>
        <comment>accuracy.xy.point_off_line</comment>
        <translation>该目标位置偏离首末两点连线 %1（最多允许 %2）</translation>
    </message>
    <message>
        <source>reading for target %1, but the line has %2 targets</source>
        <comment>accuracy.xy.no_such_point</comment>
        <translation>读数对应目标位置 %1，但该直线只有 %2 个目标位置</translation>
    </message>
    <message>
        <source>%1 does not move along this line: it is not evaluated</source>
        <comment>accuracy.xy.axis_does_not_move</comment>
        <translation>%1 轴沿该直线不运动：不予评定</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a plane: two different axis letters, such as XY</source>
        <comment>accuracy.circle.axes_invalid</comment>
        <translation>“%1”不是平面：应为两个不同的轴字母，例如 XY</translation>
    </message>
    <message>
        <source>the circle reaches %1 = %2, below the soft limit %3</source>
        <comment>accuracy.circle.below_limit</comment>
        <translation>圆到达 %1 = %2，低于软限位 %3</translation>
    </message>
    <message>
        <source>the circle reaches %1 = %2, above the soft limit %3</source>
        <comment>accuracy.circle.above_limit</comment>
        <translation>圆到达 %1 = %2，高于软限位 %3</translation>
    </message>
    <message>
        <source>choose clockwise, counter-clockwise or both</source>
        <comment>accuracy.circle.no_direction</comment>
        <translation>请选择顺时针、逆时针或两者</translation>
    </message>
    <message>
        <source>no circle was sampled</source>
        <comment>accuracy.circle.no_runs</comment>
        <translation>没有采样任何圆</translation>
    </message>
    <message>
        <source>two %1 runs: one of each direction</source>
        <comment>accuracy.circle.direction_twice</comment>
        <translation>两次%1运行：每个方向只能一次</translation>
    </message>
    <message>
        <source>%1 samples of a circle: at least %2</source>
        <comment>accuracy.circle.too_few_samples</comment>
        <translation>圆上只有 %1 个采样点：至少需要 %2 个</translation>
    </message>
    <message>
        <source>the samples leave a gap of %1 in the revolution (at most %2)</source>
        <comment>accuracy.circle.incomplete_revolution</comment>
        <translation>采样点在一周中留有 %1 的空缺（最多允许 %2）</translation>
    </message>
    <message>
        <source>the %1 samples do not lie on a circle</source>
        <comment>accuracy.circle.no_circle</comment>
        <translation>%1采样点不在一个圆上</translation>
    </message>
    <message>
        <source>%1 is written as %2, but the file&apos;s own table gives %3</source>
        <comment>accuracy.result.figure_disagrees</comment>
        <translation>%1 写的是 %2，但文件自身的表格给出 %3</translation>
    </message>
    <message>
        <source>needs mean_down_mm and s_down_mm in a bidirectional result</source>
        <comment>accuracy.result.needs_down_statistics</comment>
        <translation>双向结果需要 mean_down_mm 和 s_down_mm</translation>
    </message>
    <message>
        <source>the header has no %1 column</source>
        <comment>accuracy.csv.missing_column</comment>
        <translation>表头中没有 %1 列</translation>
    </message>
    <message>
        <source>cannot read the unit of column %1: use one of %2</source>
        <comment>accuracy.csv.unknown_unit</comment>
        <translation>无法识别 %1 列的单位：请使用 %2 之一</translation>
    </message>
    <message>
        <source>a second column for the same quantity: %1</source>
        <comment>accuracy.csv.duplicate_column</comment>
        <translation>同一物理量出现了第二列：%1</translation>
    </message>
    <message>
        <source>the file has no readings</source>
        <comment>accuracy.csv.no_readings</comment>
        <translation>文件中没有读数</translation>
    </message>
    <message>
        <source>%1 cells where the header has %2</source>
        <comment>accuracy.csv.wrong_cell_count</comment>
        <translation>有 %1 个单元格，而表头有 %2 列</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a number</source>
        <comment>accuracy.csv.not_a_number</comment>
        <translation>“%1”不是数字</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a direction: up or down</source>
        <comment>accuracy.csv.unknown_direction</comment>
        <translation>“%1”不是方向：应为 up 或 down</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a cycle: a whole number from 1</source>
        <comment>accuracy.csv.not_a_cycle</comment>
        <translation>“%1”不是循环序号：应为从 1 开始的整数</translation>
    </message>
    <message>
        <source>%1 points: a fit needs at least %2 different positions</source>
        <comment>compensation.too_few_points</comment>
        <translation>%1 个点：拟合至少需要 %2 个不同位置</translation>
    </message>
    <message>
        <source>order %1: choose %2 to %3</source>
        <comment>compensation.order_out_of_range</comment>
        <translation>阶数 %1：请选择 %2 到 %3</translation>
    </message>
    <message>
        <source>order %1 needs at least %2 points; there are %3</source>
        <comment>compensation.order_needs_more_points</comment>
        <translation>%1 阶至少需要 %2 个点；现有 %3 个</translation>
    </message>
    <message>
        <source>the polynomial has no coefficients</source>
        <comment>compensation.no_coefficients</comment>
        <translation>多项式没有系数</translation>
    </message>
    <message>
        <source>%1 coefficients: at most %2 (order 5)</source>
        <comment>compensation.too_many_coefficients</comment>
        <translation>%1 个系数：最多 %2 个（5 阶）</translation>
    </message>
    <message>
        <source>the range %1 to %2 is shorter than %3</source>
        <comment>compensation.range_too_short</comment>
        <translation>范围 %1 到 %2 短于 %3</translation>
    </message>
    <message>
        <source>the curve reaches %1 at %2, beyond ±%3</source>
        <comment>compensation.curve_too_large</comment>
        <translation>曲线在 %2 处达到 %1，超出 ±%3</translation>
    </message>
    <message>
        <source>the curve&apos;s slope is %1 µm/mm at %2, beyond %3</source>
        <comment>compensation.curve_too_steep</comment>
        <translation>曲线在 %2 处的斜率为 %1 µm/mm，超出 %3</translation>
    </message>
    <message>
        <source>%1 table points: at least %2</source>
        <comment>compensation.too_few_table_points</comment>
        <translation>%1 个表格点：至少需要 %2 个</translation>
    </message>
    <message>
        <source>%1 table points: a device keeps at most %2</source>
        <comment>compensation.too_many_table_points</comment>
        <translation>%1 个表格点：设备最多保存 %2 个</translation>
    </message>
    <message>
        <source>nominal %1 does not come after %2</source>
        <comment>compensation.nominals_not_increasing</comment>
        <translation>名义位置 %1 不大于 %2</translation>
    </message>
    <message>
        <source>nominals %1 and %2 are closer than %3</source>
        <comment>compensation.nominals_too_close</comment>
        <translation>名义位置 %1 与 %2 相距小于 %3</translation>
    </message>
    <message>
        <source>a backlash of %1 beside per-direction columns: put it in the columns</source>
        <comment>compensation.backlash_with_directions</comment>
        <translation>已有分方向的列，又给出反向间隙 %1：请把它并入各列</translation>
    </message>
    <message>
        <source>%1 values on a line where LinuxCNC expects three (nominal, forward, reverse); LinuxCNC would stop reading here</source>
        <comment>compensation.linuxcnc.not_a_triplet</comment>
        <translation>一行有 %1 个数，而 LinuxCNC 要求三个（名义、正向、反向）；LinuxCNC 读到这里会停止</translation>
    </message>
    <message>
        <source>up</source>
        <comment>direction.up</comment>
        <translation>正向</translation>
    </message>
    <message>
        <source>down</source>
        <comment>direction.down</comment>
        <translation>反向</translation>
    </message>
    <message>
        <source>clockwise</source>
        <comment>rotation.cw</comment>
        <translation>顺时针</translation>
    </message>
    <message>
        <source>counter-clockwise</source>
        <comment>rotation.ccw</comment>
        <translation>逆时针</translation>
    </message>
    <message>
        <source>the first line must be &apos;# %1 1&apos;: this is not a scale certificate</source>
        <comment>accuracy.certificate.no_schema</comment>
        <translation>第一行必须是“# %1 1”：这不是线纹尺校准证书</translation>
    </message>
    <message>
        <source>a certificate of version %1; this BenchPilot reads version %2</source>
        <comment>accuracy.certificate.version</comment>
        <translation>证书版本为 %1；此版本 BenchPilot 读取版本 %2</translation>
    </message>
    <message>
        <source>graduation %1 is outside the scale, which is graduated from 0 to %2: a certificate of another scale</source>
        <comment>accuracy.certificate.outside_scale</comment>
        <translation>刻线 %1 超出线纹尺范围（刻度从 0 到 %2）：这是另一把尺的证书</translation>
    </message>
    <message>
        <source>graduation %1 is not on the scale&apos;s pitch of %2: a certificate of another scale</source>
        <comment>accuracy.certificate.off_pitch</comment>
        <translation>刻线 %1 不在线纹尺的刻线间距 %2 上：这是另一把尺的证书</translation>
    </message>
    <message>
        <source>graduation %1 does not come after %2: a certificate&apos;s graduations increase</source>
        <comment>accuracy.certificate.not_increasing</comment>
        <translation>刻线 %1 不在 %2 之后：证书中的刻线必须递增</translation>
    </message>
</context>
<context>
    <name>ui::words::CameraWords</name>
    <message>
        <source>no camera is chosen</source>
        <comment>camera.none</comment>
        <translation>未选择相机</translation>
    </message>
    <message>
        <source>the camera %1 is not open</source>
        <comment>camera.not_open</comment>
        <translation>相机 %1 未打开</translation>
    </message>
    <message>
        <source>the camera %1 was closed while it took an image</source>
        <comment>camera.closed_during_capture</comment>
        <translation>相机 %1 在拍摄图像时被关闭</translation>
    </message>
    <message>
        <source>the simulated camera has no simulated stage to look at (is the simulator connected?)</source>
        <comment>camera.sim.no_stage</comment>
        <translation>模拟相机没有可观察的模拟载物台（模拟器已连接吗？）</translation>
    </message>
    <message>
        <source>the simulated camera &apos;sim&apos; looks at the in-process simulator&apos;s stage: use it with --sim stage (benchpilot-sim&apos;s camera is sim:PATH)</source>
        <comment>camera.sim.needs_simulator</comment>
        <translation>模拟相机 &apos;sim&apos; 观察的是进程内模拟器的载物台：请与 --sim stage 一起使用（benchpilot-sim 的相机是 sim:PATH）</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a camera: give sim, sim:PATH, uvc[:NAME], command:CMD or folder:DIR</source>
        <comment>camera.source.unknown</comment>
        <translation>&apos;%1&apos; 不是相机：请给出 sim、sim:PATH、uvc[:NAME]、command:CMD 或 folder:DIR</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: %2: needs what follows the colon (%2:…)</source>
        <comment>camera.source.needs_argument</comment>
        <translation>&apos;%1&apos;：%2：冒号后面需要内容（%2:…）</translation>
    </message>
    <message>
        <source>the camera source &apos;%1&apos; is not in this build of BenchPilot yet; &apos;camera list&apos; shows what is</source>
        <comment>camera.source.not_available</comment>
        <translation>本版本的 BenchPilot 尚未提供相机来源 &apos;%1&apos;；&apos;camera list&apos; 列出可用的来源</translation>
    </message>
    <message>
        <source>the camera %1 gives images of %2 × %3 px, but the plan&apos;s camera has %4 × %5 px: correct the plan&apos;s sensor (or the camera&apos;s resolution), or every tile lands in the wrong place</source>
        <comment>camera.sensor_mismatch</comment>
        <translation>相机 %1 给出的图像为 %2 × %3 像素，而计划中的相机为 %4 × %5 像素：请更正计划的传感器（或相机的分辨率），否则每个图块都会放错位置</translation>
    </message>
    <message>
        <source>cannot write the image %1: %2</source>
        <comment>camera.tiff.cannot_write</comment>
        <translation>无法写入图像 %1：%2</translation>
    </message>
    <message>
        <source>cannot read the image %1: %2</source>
        <comment>camera.tiff.cannot_read</comment>
        <translation>无法读取图像 %1：%2</translation>
    </message>
    <message>
        <source>the image %1 is %2 a pixel; BenchPilot reads 8- or 16-bit grey and 8-bit RGB</source>
        <comment>camera.tiff.unsupported</comment>
        <translation>图像 %1 每像素为 %2；BenchPilot 读取 8 位或 16 位灰度以及 8 位 RGB</translation>
    </message>
    <message>
        <source>the camera gave an empty image; nothing was written to %1</source>
        <comment>camera.tiff.empty_frame</comment>
        <translation>相机给出了空图像；未向 %1 写入任何内容</translation>
    </message>
    <message>
        <source>the capture command &apos;%1&apos; failed (exit code %2): %3</source>
        <comment>camera.command.failed</comment>
        <translation>采集命令 &apos;%1&apos; 失败（退出码 %2）：%3</translation>
    </message>
    <message>
        <source>the capture command &apos;%1&apos; did not finish within %2 and was stopped: %3</source>
        <comment>camera.command.timeout</comment>
        <translation>采集命令 &apos;%1&apos; 未在 %2 内结束，已被终止：%3</translation>
    </message>
    <message>
        <source>the capture command &apos;%1&apos; ended without writing %2: %3</source>
        <comment>camera.command.no_file</comment>
        <translation>采集命令 &apos;%1&apos; 结束时没有写出 %2：%3</translation>
    </message>
    <message>
        <source>the capture command &apos;%1&apos; cannot be started: %2</source>
        <comment>camera.command.cannot_start</comment>
        <translation>无法启动采集命令 &apos;%1&apos;：%2</translation>
    </message>
    <message>
        <source>the capture command &apos;%1&apos; is still taking the previous image</source>
        <comment>camera.command.busy</comment>
        <translation>采集命令 &apos;%1&apos; 仍在拍摄上一张图像</translation>
    </message>
    <message>
        <source>the camera&apos;s folder %1 is not there (or not a folder)</source>
        <comment>camera.folder.missing</comment>
        <translation>相机的文件夹 %1 不存在（或不是文件夹）</translation>
    </message>
    <message>
        <source>no new image arrived in %1 within %2: is the camera&apos;s software running and saving there, and is it fired by the stage&apos;s trigger output?</source>
        <comment>camera.folder.timeout</comment>
        <translation>%2 内 %1 中没有出现新图像：相机软件是否在运行并保存到那里？是否由载物台的触发输出触发？</translation>
    </message>
    <message>
        <source>still waiting for the previous image in %1</source>
        <comment>camera.folder.busy</comment>
        <translation>仍在等待 %1 中的上一张图像</translation>
    </message>
    <message>
        <source>no USB camera is attached (Qt Multimedia finds none), so &apos;%1&apos; cannot be opened</source>
        <comment>camera.uvc.none_found</comment>
        <translation>未连接 USB 相机（Qt Multimedia 一个也没找到），因此无法打开“%1”</translation>
    </message>
    <message>
        <source>there is no USB camera &apos;%1&apos;; the cameras found are: %2 (give uvc:NAME with a name or an id from &apos;camera list&apos;)</source>
        <comment>camera.uvc.not_found</comment>
        <translation>没有 USB 相机“%1”；找到的相机为：%2（请用“camera list”中的名称或 id 写成 uvc:NAME）</translation>
    </message>
    <message>
        <source>the camera %1 has no %2 × %3 px format that BenchPilot can read; it offers %4</source>
        <comment>camera.uvc.no_such_resolution</comment>
        <translation>相机 %1 没有 BenchPilot 能读取的 %2 × %3 像素格式；它提供 %4</translation>
    </message>
    <message>
        <source>the camera %1 sends none of the pixel formats BenchPilot reads (it offers %2)</source>
        <comment>camera.uvc.no_format</comment>
        <translation>相机 %1 发送的像素格式 BenchPilot 都无法读取（它提供 %2）</translation>
    </message>
    <message>
        <source>the camera %1 gives %2 × %3 px, and has no format of the plan&apos;s sensor, %4 × %5 px (it offers %6): correct the plan&apos;s sensor, or every tile lands in the wrong place</source>
        <comment>camera.uvc.sensor_mismatch</comment>
        <translation>相机 %1 给出 %2 × %3 像素，且没有计划中传感器的 %4 × %5 像素格式（它提供 %6）：请更正计划的传感器，否则每个图块都会放错位置</translation>
    </message>
    <message>
        <source>the camera %1 did not start within %2: is another program using it?</source>
        <comment>camera.uvc.open_timeout</comment>
        <translation>相机 %1 未在 %2 内启动：是否有其他程序正在使用它？</translation>
    </message>
    <message>
        <source>the camera %1 gave no new frame within %2</source>
        <comment>camera.uvc.timeout</comment>
        <translation>相机 %1 在 %2 内没有给出新的帧</translation>
    </message>
    <message>
        <source>the camera %1 failed: %2</source>
        <comment>camera.uvc.error</comment>
        <translation>相机 %1 出错：%2</translation>
    </message>
    <message>
        <source>the camera %1 was unplugged (it is no longer in the system&apos;s list of cameras)</source>
        <comment>camera.uvc.unplugged</comment>
        <translation>相机 %1 已被拔出（它已不在系统的相机列表中）</translation>
    </message>
    <message>
        <source>the camera %1 is still taking the previous image</source>
        <comment>camera.uvc.busy</comment>
        <translation>相机 %1 仍在拍摄上一张图像</translation>
    </message>
    <message>
        <source>the camera sends %1 frames (%2 × %3 px), which BenchPilot cannot read: choose one of its other formats (see docs/camera.md)</source>
        <comment>camera.uvc.format_unsupported</comment>
        <translation>相机发送的是 %1 帧（%2 × %3 像素），BenchPilot 无法读取：请选择它的其他格式（见 docs/camera.md）</translation>
    </message>
    <message>
        <source>a %1 frame of %2 × %3 px from the camera could not be read from its buffer</source>
        <comment>camera.uvc.cannot_map</comment>
        <translation>无法从缓冲区读取相机的一帧 %1（%2 × %3 像素）</translation>
    </message>
    <message>
        <source>a %1 frame from the camera holds fewer bytes than %2 × %3 px need</source>
        <comment>camera.uvc.short_frame</comment>
        <translation>相机的一帧 %1 所含字节少于 %2 × %3 像素所需</translation>
    </message>
    <message>
        <source>no simulated camera is served at %1: start benchpilot-sim with --camera-socket %1</source>
        <comment>camera.socket.no_server</comment>
        <translation>%1 上没有提供模拟相机：请以 --camera-socket %1 启动 benchpilot-sim</translation>
    </message>
    <message>
        <source>the simulated camera at %1 went away (has benchpilot-sim stopped?)</source>
        <comment>camera.socket.lost</comment>
        <translation>%1 上的模拟相机已断开（benchpilot-sim 已停止？）</translation>
    </message>
    <message>
        <source>the simulated camera at %1 did not answer within %2</source>
        <comment>camera.socket.timeout</comment>
        <translation>%1 上的模拟相机在 %2 内没有应答</translation>
    </message>
    <message>
        <source>the simulated camera at %1 sent what cannot be read: %2</source>
        <comment>camera.socket.garbled</comment>
        <translation>%1 上的模拟相机发来了无法读取的内容：%2</translation>
    </message>
    <message>
        <source>the simulated camera at %1 refused the request: %2 (%3)</source>
        <comment>camera.socket.server_error</comment>
        <translation>%1 上的模拟相机拒绝了请求：%2（%3）</translation>
    </message>
    <message>
        <source>the socket path %1 is empty or too long (a local socket&apos;s path has at most %2)</source>
        <comment>camera.socket.path_too_long</comment>
        <translation>套接字路径 %1 为空或太长（本地套接字的路径最多 %2）</translation>
    </message>
    <message>
        <source>%1 exists and is not a socket: refusing to replace it</source>
        <comment>camera.socket.not_a_socket</comment>
        <translation>%1 已存在且不是套接字：拒绝替换它</translation>
    </message>
    <message>
        <source>a simulated camera is already served at %1 (another benchpilot-sim?): stop it or give another path</source>
        <comment>camera.socket.in_use</comment>
        <translation>%1 上已有模拟相机在提供服务（另一个 benchpilot-sim？）：请停止它或换一个路径</translation>
    </message>
    <message>
        <source>cannot serve the simulated camera at %1: %2</source>
        <comment>camera.socket.cannot_listen</comment>
        <translation>无法在 %1 上提供模拟相机：%2</translation>
    </message>
    <message>
        <source>a header line longer than %1</source>
        <comment>camera.wire.header_too_long</comment>
        <translation>头部行长于 %1</translation>
    </message>
    <message>
        <source>a header that is not a JSON object (%1)</source>
        <comment>camera.wire.not_json</comment>
        <translation>头部不是 JSON 对象（%1）</translation>
    </message>
    <message>
        <source>a message of schema &apos;%1&apos;, not benchpilot.sim-camera</source>
        <comment>camera.wire.schema</comment>
        <translation>消息的 schema 为 &apos;%1&apos;，而不是 benchpilot.sim-camera</translation>
    </message>
    <message>
        <source>a message of version %1; this BenchPilot reads version %2</source>
        <comment>camera.wire.version</comment>
        <translation>消息版本为 %1；本 BenchPilot 读取版本 %2</translation>
    </message>
    <message>
        <source>the field &apos;%1&apos; is missing or out of range</source>
        <comment>camera.wire.field</comment>
        <translation>字段 &apos;%1&apos; 缺失或超出范围</translation>
    </message>
    <message>
        <source>a &apos;%1&apos; message where none belongs</source>
        <comment>camera.wire.unexpected</comment>
        <translation>此处不应出现 &apos;%1&apos; 消息</translation>
    </message>
    <message>
        <source>a frame of %3 × %4 px announces %1 of pixels where it needs %2</source>
        <comment>camera.wire.size</comment>
        <translation>%3 × %4 像素的帧声明了 %1 的像素数据，而应为 %2</translation>
    </message>
    <message>
        <source>the camera %1 gave no image in %2</source>
        <comment>camera.reading.silent</comment>
        <translation>相机 %1 在 %2 内没有给出图像</translation>
    </message>
    <message>
        <source>the camera %1 reads a glass scale along one axis, X or Y, at a time</source>
        <comment>camera.reading.one_axis</comment>
        <translation>相机 %1 一次只读取沿一个轴（X 或 Y）的玻璃线纹尺</translation>
    </message>
    <message>
        <source>%1; the image is kept as %2</source>
        <comment>camera.reading.no_line</comment>
        <translation>%1；图像已保存为 %2</translation>
    </message>
    <message>
        <source>%1; the image is kept as %2</source>
        <comment>camera.reading.no_dot</comment>
        <translation>%1；图像已保存为 %2</translation>
    </message>
    <message>
        <source>the camera %1 reads a grid plate&apos;s dot in X and Y at once: a reading needs both</source>
        <comment>camera.reading.two_axes</comment>
        <translation>相机 %1 同时读取网格板圆点的 X 和 Y：一次读数需要两者</translation>
    </message>
    <message>
        <source>what the camera found is %1 across, not one of the plate&apos;s dots of %2</source>
        <comment>camera.reading.dot_size</comment>
        <translation>相机找到的目标直径为 %1，不是网格板上直径 %2 的圆点</translation>
    </message>
    <message>
        <source>the nearest dot is %1 from the image centre, more than half the plate&apos;s pitch (%2): not this node&apos;s dot</source>
        <comment>camera.reading.dot_far</comment>
        <translation>最近的圆点距图像中心 %1，超过网格板间距的一半（%2）：不是此节点的圆点</translation>
    </message>
    <message>
        <source>a %1 (Motion-JPEG) frame from the camera, %2 × %3 px, could not be decoded</source>
        <comment>camera.uvc.jpeg_unreadable</comment>
        <translation>无法解码相机的一帧 %1（Motion-JPEG），%2 × %3 像素</translation>
    </message>
    <message>
        <source>a camera calibration is already running</source>
        <comment>camera.calibration.already_running</comment>
        <translation>相机标定已在运行</translation>
    </message>
    <message>
        <source>the stage is not connected</source>
        <comment>camera.calibration.not_connected</comment>
        <translation>载物台未连接</translation>
    </message>
    <message>
        <source>the camera is calibrated against the microscope stage; this instrument is not one</source>
        <comment>camera.calibration.not_a_stage</comment>
        <translation>相机需相对显微镜载物台标定；此仪器不是载物台</translation>
    </message>
    <message>
        <source>the E-stop is latched: reset it before calibrating the camera</source>
        <comment>camera.calibration.estop_latched</comment>
        <translation>急停已锁定：标定相机前请先复位</translation>
    </message>
    <message>
        <source>the stage is not homed: home it before calibrating the camera</source>
        <comment>camera.calibration.not_homed</comment>
        <translation>载物台未回零：标定相机前请先回零</translation>
    </message>
    <message>
        <source>the stage is moving: wait until it stands still</source>
        <comment>camera.calibration.moving</comment>
        <translation>载物台正在移动：请等它停稳</translation>
    </message>
    <message>
        <source>a step of %1 px taken %2 times each way is not a calibration: the step must be 1 to 10000 px and the count 1 to 10</source>
        <comment>camera.calibration.bad_steps</comment>
        <translation>每个方向走 %2 次、每步 %1 px 无法构成标定：步距须为 1 到 10000 px，次数须为 1 到 10</translation>
    </message>
    <message>
        <source>the camera %1 does not say its pixel size: give the nominal one (--pixel-um)</source>
        <comment>camera.calibration.no_pixel_size</comment>
        <translation>相机 %1 未给出其像素尺寸：请给出标称值（--pixel-um）</translation>
    </message>
    <message>
        <source>the steps reach %1 px from the start, more than half of the %2 × %3 px image: take shorter or fewer steps</source>
        <comment>camera.calibration.steps_too_long</comment>
        <translation>步距离起点可达 %1 px，超过 %2 × %3 px 图像的一半：请缩短步距或减少步数</translation>
    </message>
    <message>
        <source>a step would take %1 to %2, outside its soft limits %3 … %4: move the stage further in first</source>
        <comment>camera.calibration.beyond_limits</comment>
        <translation>某一步会使 %1 到达 %2，超出其软限位 %3 … %4：请先把载物台移到更靠内的位置</translation>
    </message>
    <message>
        <source>the camera&apos;s image changed size during the calibration (%1 × %2 px, the first was %3 × %4 px)</source>
        <comment>camera.calibration.size_changed</comment>
        <translation>标定过程中相机图像尺寸发生了变化（%1 × %2 px，第一张为 %3 × %4 px）</translation>
    </message>
    <message>
        <source>the camera calibration was stopped; the stage was stopped where it stood</source>
        <comment>camera.calibration.stopped</comment>
        <translation>相机标定已停止；载物台已在原处停下</translation>
    </message>
    <message>
        <source>the link to the stage was lost during the camera calibration</source>
        <comment>camera.calibration.link_lost</comment>
        <translation>相机标定过程中与载物台的连接中断</translation>
    </message>
    <message>
        <source>the camera calibration stopped: %1 %2</source>
        <comment>camera.calibration.stage_event</comment>
        <translation>相机标定已停止：%1 %2</translation>
    </message>
    <message>
        <source>the stage refused a calibration step: %1</source>
        <comment>camera.calibration.move_refused</comment>
        <translation>载物台拒绝了一个标定步：%1</translation>
    </message>
    <message>
        <source>a calibration step did not end within %1</source>
        <comment>camera.calibration.move_timeout</comment>
        <translation>一个标定步未在 %1 内完成</translation>
    </message>
    <message>
        <source>the camera gave no image within %1</source>
        <comment>camera.calibration.no_image</comment>
        <translation>相机在 %1 内没有给出图像</translation>
    </message>
    <message>
        <source>the camera failed during the calibration: %1</source>
        <comment>camera.calibration.camera_failed</comment>
        <translation>标定过程中相机出错：%1</translation>
    </message>
    <message>
        <source>only %1 of %2 images could be registered against the first: the specimen has too little texture here, or the steps are too long</source>
        <comment>camera.calibration.not_registered</comment>
        <translation>%2 张图像中只有 %1 张能与第一张配准：此处样品纹理太少，或步距太长</translation>
    </message>
    <message>
        <source>the registered shifts do not give a camera mapping (the steps do not span both axes)</source>
        <comment>camera.calibration.no_fit</comment>
        <translation>配准得到的位移无法给出相机映射（各步未覆盖两个轴）</translation>
    </message>
</context>
<context>
    <name>ui::words::CapabilityWords</name>
    <message>
        <source>homing switches</source>
        <translation>零位开关</translation>
    </message>
    <message>
        <source>way to set an axis&apos; zero</source>
        <translation>设定轴零点的功能</translation>
    </message>
    <message>
        <source>encoder or grating readings</source>
        <translation>编码器或光栅尺读数</translation>
    </message>
    <message>
        <source>closed position loop</source>
        <translation>位置闭环</translation>
    </message>
    <message>
        <source>telemetry stream</source>
        <translation>遥测数据流</translation>
    </message>
    <message>
        <source>continuous jog</source>
        <translation>连续点动</translation>
    </message>
    <message>
        <source>way to stop by itself when BenchPilot goes quiet</source>
        <translation>BenchPilot 无响应时自行停止的功能</translation>
    </message>
    <message>
        <source>path queue to run patterns on</source>
        <translation>运行图形用的路径队列</translation>
    </message>
    <message>
        <source>Z axis that follows a path</source>
        <translation>跟随路径的 Z 轴</translation>
    </message>
    <message>
        <source>Z axis that waits for X and Y</source>
        <translation>等待 X、Y 到位的 Z 轴</translation>
    </message>
    <message>
        <source>soft limits of its own</source>
        <translation>自身的软限位</translation>
    </message>
    <message>
        <source>PID gains to tune</source>
        <translation>可整定的 PID 增益</translation>
    </message>
    <message>
        <source>step or relay tests</source>
        <translation>阶跃或继电测试</translation>
    </message>
    <message>
        <source>plunger pump</source>
        <translation>柱塞泵</translation>
    </message>
    <message>
        <source>trigger output for a camera</source>
        <translation>相机触发输出</translation>
    </message>
    <message>
        <source>report of its acceleration and jerk limits</source>
        <translation>加速度与加加速度限值的报告</translation>
    </message>
    <message>
        <source>stage</source>
        <translation>载物台</translation>
    </message>
    <message>
        <source>analyzer</source>
        <translation>分析仪</translation>
    </message>
    <message>
        <source>it runs open loop</source>
        <translation>它以开环运行</translation>
    </message>
    <message>
        <source>its firmware predates them; estimates assume the reference machine&apos;s</source>
        <translation>其固件早于该功能；估算按参考机器的数值</translation>
    </message>
    <message>
        <source>its protocol has none</source>
        <translation>其协议不支持</translation>
    </message>
    <message>
        <source>The instrument is not connected.</source>
        <translation>仪器未连接。</translation>
    </message>
    <message>
        <source>The %1 is not connected.</source>
        <translation>%1未连接。</translation>
    </message>
    <message>
        <source>The %1</source>
        <translation>%1</translation>
    </message>
    <message>
        <source>The %1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <source>%1 has no %2.</source>
        <translation>%1没有%2。</translation>
    </message>
    <message>
        <source>%1 has no %2: %3.</source>
        <translation>%1没有%2：%3。</translation>
    </message>
    <message>
        <source>error compensation of its own</source>
        <translation>自身的误差补偿</translation>
    </message>
    <message>
        <source>arched move that blends Z with X and Y</source>
        <translation>将 Z 与 X、Y 融合的拱形移动</translation>
    </message>
</context>
<context>
    <name>ui::words::DeviceWords</name>
    <message>
        <source>%1 not sent: the instrument is not connected</source>
        <comment>request.not_sent</comment>
        <translation>%1 未发送：仪器未连接</translation>
    </message>
    <message>
        <source>no reply to %1 after %2 attempts (%3): the device is not answering</source>
        <comment>request.no_reply</comment>
        <translation>%1 尝试 %2 次（%3）均无应答：设备没有响应</translation>
    </message>
    <message>
        <source>%1 abandoned: %2</source>
        <comment>request.abandoned</comment>
        <translation>%1 已放弃：%2</translation>
    </message>
    <message>
        <source>%1 refused with an unreadable error</source>
        <comment>request.unreadable_error</comment>
        <translation>%1 被拒绝，错误信息无法解读</translation>
    </message>
    <message>
        <source>%1 refused: %2</source>
        <comment>request.refused</comment>
        <translation>%1被拒绝：%2</translation>
    </message>
    <message>
        <source>the instrument is not connected</source>
        <comment>request.instrument_not_connected</comment>
        <translation>仪器未连接</translation>
    </message>
    <message>
        <source>move: no axis given</source>
        <comment>request.move_no_axis</comment>
        <translation>移动：未指定轴</translation>
    </message>
    <message>
        <source>move: axis %1 does not exist on this instrument</source>
        <comment>request.move_no_such_axis</comment>
        <translation>移动：该仪器没有第 %1 轴</translation>
    </message>
    <message>
        <source>move: axis %1 target is not a number</source>
        <comment>request.move_target_not_number</comment>
        <translation>移动：%1 轴的目标不是数字</translation>
    </message>
    <message>
        <source>move: axis %1 named twice</source>
        <comment>request.move_axis_twice</comment>
        <translation>移动：%1 轴被指定了两次</translation>
    </message>
    <message>
        <source>move: speed must be a positive number</source>
        <comment>request.move_bad_speed</comment>
        <translation>移动：速度必须为正数</translation>
    </message>
    <message>
        <source>jog step: bad axis, step or speed</source>
        <comment>request.jog_step_invalid</comment>
        <translation>步进点动：轴、步长或速度无效</translation>
    </message>
    <message>
        <source>jog: bad axis or velocity</source>
        <comment>request.jog_invalid</comment>
        <translation>点动：轴或速度无效</translation>
    </message>
    <message>
        <source>soft limits: bad axis or value</source>
        <comment>request.soft_limits_invalid</comment>
        <translation>软限位：轴或数值无效</translation>
    </message>
    <message>
        <source>dwell: %1 is not a time to wait</source>
        <comment>request.dwell_invalid</comment>
        <translation>停留：%1 不是有效的等待时间</translation>
    </message>
    <message>
        <source>dwell abandoned: the link went down</source>
        <comment>request.dwell_link_down</comment>
        <translation>停留已放弃：连接已断开</translation>
    </message>
    <message>
        <source>this instrument has no trigger output (protocol 1 has none)</source>
        <comment>request.no_trigger_output</comment>
        <translation>该仪器没有触发输出（协议 1 不支持）</translation>
    </message>
    <message>
        <source>telemetry: %1</source>
        <comment>request.telemetry_refused</comment>
        <translation>遥测：%1</translation>
    </message>
    <message>
        <source>the instrument answered a path request with something unreadable</source>
        <comment>request.path_unreadable</comment>
        <translation>仪器对路径请求的应答无法解读</translation>
    </message>
    <message>
        <source>the device answered GET_GAINS with something unreadable</source>
        <comment>request.gains_unreadable</comment>
        <translation>设备对 GET_GAINS 的应答无法解读</translation>
    </message>
    <message>
        <source>step %1 is not a usable step size</source>
        <comment>request.step_size_invalid</comment>
        <translation>%1 不是可用的阶跃幅值</translation>
    </message>
    <message>
        <source>the device answered GET_CAPTURE with something unreadable</source>
        <comment>request.capture_unreadable</comment>
        <translation>设备对 GET_CAPTURE 的应答无法解读</translation>
    </message>
    <message>
        <source>a new test replaced the capture while it was being read</source>
        <comment>request.capture_replaced</comment>
        <translation>读取采集数据时，新的测试覆盖了它</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <comment>device.refused</comment>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>no connection chosen</source>
        <comment>link.no_connection_chosen</comment>
        <translation>未选择连接</translation>
    </message>
    <message>
        <source>disconnected</source>
        <comment>link.disconnected</comment>
        <translation>已断开连接</translation>
    </message>
    <message>
        <source>link lost: %1</source>
        <comment>link.lost</comment>
        <translation>连接中断：%1</translation>
    </message>
    <message>
        <source>no answer from %1: check power, cable and baud rate</source>
        <comment>link.no_answer</comment>
        <translation>%1 无应答：请检查电源、线缆和波特率</translation>
    </message>
    <message>
        <source>%1 answered HELLO with something that is not BenchPilot protocol</source>
        <comment>link.not_benchpilot</comment>
        <translation>%1 对 HELLO 的应答不是 BenchPilot 协议</translation>
    </message>
    <message>
        <source>the device speaks protocol version %1; this BenchPilot speaks version %2</source>
        <comment>link.protocol_version</comment>
        <translation>设备使用协议版本 %1；本 BenchPilot 使用版本 %2</translation>
    </message>
    <message>
        <source>the device stopped answering</source>
        <comment>link.stopped_answering</comment>
        <translation>设备停止了响应</translation>
    </message>
    <message>
        <source>the simulated cable is unplugged</source>
        <comment>link.cable_unplugged</comment>
        <translation>仿真线缆已拔出</translation>
    </message>
    <message>
        <source>the simulated cable was unplugged</source>
        <comment>link.cable_pulled</comment>
        <translation>仿真线缆被拔出</translation>
    </message>
    <message>
        <source>%1: device went away (%2)</source>
        <comment>link.port_went_away</comment>
        <translation>%1：设备已断开（%2）</translation>
    </message>
    <message>
        <source>cannot open %1: no such port</source>
        <comment>link.no_such_port</comment>
        <translation>无法打开 %1：端口不存在</translation>
    </message>
    <message>
        <source>cannot open %1: %2</source>
        <comment>link.cannot_open</comment>
        <translation>无法打开 %1：%2</translation>
    </message>
    <message>
        <source>%1 telemetry not subscribed: %2</source>
        <comment>telemetry.not_subscribed</comment>
        <translation>%1 遥测未能订阅：%2</translation>
    </message>
    <message>
        <source>rate limited to %1 by the %2 link (it carries at most %3 with %4 channels)</source>
        <comment>telemetry.rate_link_limited</comment>
        <translation>速率受 %2 链路限制为 %1（%4 个通道时最多 %3）</translation>
    </message>
    <message>
        <source>rate limited to %1 by the device&apos;s %2 sample clock</source>
        <comment>telemetry.rate_clock_limited</comment>
        <translation>速率受设备 %2 采样时钟限制为 %1</translation>
    </message>
    <message>
        <source>the device streams at %1, the nearest its sample clock makes</source>
        <comment>telemetry.rate_nearest</comment>
        <translation>设备以 %1 发送数据，这是其采样时钟能达到的最接近值</translation>
    </message>
    <message>
        <source>%1</source>
        <comment>telemetry.link_state</comment>
        <translation>%1</translation>
    </message>
    <message>
        <source>already recording to %1</source>
        <comment>telemetry.already_recording</comment>
        <translation>已在记录到 %1</translation>
    </message>
    <message>
        <source>nothing to record: choose at least one channel of a connected instrument</source>
        <comment>telemetry.nothing_to_record</comment>
        <translation>没有可记录的数据：请至少选择一台已连接仪器的一个通道</translation>
    </message>
    <message>
        <source>recording to %1 stopped: %2</source>
        <comment>telemetry.recording_stopped</comment>
        <translation>记录到 %1 已停止：%2</translation>
    </message>
    <message>
        <source>home</source>
        <comment>request.home</comment>
        <translation>回零</translation>
    </message>
    <message>
        <source>move</source>
        <comment>request.move</comment>
        <translation>移动</translation>
    </message>
    <message>
        <source>jog step</source>
        <comment>request.jog_step</comment>
        <translation>步进点动</translation>
    </message>
    <message>
        <source>jog</source>
        <comment>request.jog</comment>
        <translation>点动</translation>
    </message>
    <message>
        <source>stop</source>
        <comment>request.stop</comment>
        <translation>停止</translation>
    </message>
    <message>
        <source>E-stop</source>
        <comment>request.estop</comment>
        <translation>急停</translation>
    </message>
    <message>
        <source>reset</source>
        <comment>request.reset</comment>
        <translation>复位</translation>
    </message>
    <message>
        <source>set zero</source>
        <comment>request.set_zero</comment>
        <translation>设零点</translation>
    </message>
    <message>
        <source>soft limits</source>
        <comment>request.soft_limits</comment>
        <translation>软限位设置</translation>
    </message>
    <message>
        <source>path</source>
        <comment>request.path</comment>
        <translation>路径</translation>
    </message>
    <message>
        <source>path segments</source>
        <comment>request.path_segments</comment>
        <translation>路径段</translation>
    </message>
    <message>
        <source>pause</source>
        <comment>request.pause</comment>
        <translation>暂停</translation>
    </message>
    <message>
        <source>resume</source>
        <comment>request.resume</comment>
        <translation>继续</translation>
    </message>
    <message>
        <source>abort</source>
        <comment>request.abort</comment>
        <translation>中止</translation>
    </message>
    <message>
        <source>get gains</source>
        <comment>request.get_gains</comment>
        <translation>读取增益</translation>
    </message>
    <message>
        <source>set gains</source>
        <comment>request.set_gains</comment>
        <translation>设置增益</translation>
    </message>
    <message>
        <source>step test</source>
        <comment>request.step_test</comment>
        <translation>阶跃测试</translation>
    </message>
    <message>
        <source>relay test</source>
        <comment>request.relay_test</comment>
        <translation>继电测试</translation>
    </message>
    <message>
        <source>abort test</source>
        <comment>request.abort_test</comment>
        <translation>中止测试</translation>
    </message>
    <message>
        <source>read capture</source>
        <comment>request.read_capture</comment>
        <translation>读取采集数据</translation>
    </message>
    <message>
        <source>unknown command</source>
        <comment>device.error.unknown_command</comment>
        <translation>未知命令</translation>
    </message>
    <message>
        <source>bad payload</source>
        <comment>device.error.bad_payload</comment>
        <translation>数据内容无效</translation>
    </message>
    <message>
        <source>bad axis</source>
        <comment>device.error.bad_axis</comment>
        <translation>轴无效</translation>
    </message>
    <message>
        <source>axis not homed</source>
        <comment>device.error.not_homed</comment>
        <translation>轴未回零</translation>
    </message>
    <message>
        <source>soft limit</source>
        <comment>device.error.soft_limit</comment>
        <translation>超出软限位</translation>
    </message>
    <message>
        <source>busy</source>
        <comment>device.error.busy</comment>
        <translation>设备忙</translation>
    </message>
    <message>
        <source>E-stop active</source>
        <comment>device.error.estop_active</comment>
        <translation>急停已触发</translation>
    </message>
    <message>
        <source>over link capacity</source>
        <comment>device.error.over_capacity</comment>
        <translation>超出链路容量</translation>
    </message>
    <message>
        <source>out of range</source>
        <comment>device.error.out_of_range</comment>
        <translation>超出范围</translation>
    </message>
    <message>
        <source>fault</source>
        <comment>device.error.fault</comment>
        <translation>故障</translation>
    </message>
    <message>
        <source>gains refused</source>
        <comment>device.error.bad_gains</comment>
        <translation>增益被拒绝</translation>
    </message>
    <message>
        <source>a test is running</source>
        <comment>device.error.test_active</comment>
        <translation>测试正在进行</translation>
    </message>
    <message>
        <source>no closed loop to tune</source>
        <comment>device.error.not_closed_loop</comment>
        <translation>无可整定的闭环</translation>
    </message>
    <message>
        <source>nothing captured</source>
        <comment>device.error.no_capture</comment>
        <translation>没有采集数据</translation>
    </message>
    <message>
        <source>path queue full</source>
        <comment>device.error.path_queue_full</comment>
        <translation>路径队列已满</translation>
    </message>
    <message>
        <source>path segment out of sequence</source>
        <comment>device.error.path_sequence</comment>
        <translation>路径段顺序错误</translation>
    </message>
    <message>
        <source>bad path segment</source>
        <comment>device.error.path_geometry</comment>
        <translation>路径段无效</translation>
    </message>
    <message>
        <source>no path to add to</source>
        <comment>device.error.path_state</comment>
        <translation>没有可追加的路径</translation>
    </message>
    <message>
        <source>unknown error</source>
        <comment>device.error.unknown</comment>
        <translation>未知错误</translation>
    </message>
    <message>
        <source>motion done</source>
        <comment>device.event.motion_done</comment>
        <translation>运动完成</translation>
    </message>
    <message>
        <source>home done</source>
        <comment>device.event.home_done</comment>
        <translation>回零完成</translation>
    </message>
    <message>
        <source>limit hit</source>
        <comment>device.event.limit_hit</comment>
        <translation>触发限位</translation>
    </message>
    <message>
        <source>fault</source>
        <comment>device.event.fault</comment>
        <translation>故障</translation>
    </message>
    <message>
        <source>E-stop</source>
        <comment>device.event.estop</comment>
        <translation>急停</translation>
    </message>
    <message>
        <source>jog expired</source>
        <comment>device.event.jog_expired</comment>
        <translation>点动超时停止</translation>
    </message>
    <message>
        <source>stopped</source>
        <comment>device.event.stopped</comment>
        <translation>已停止</translation>
    </message>
    <message>
        <source>lost steps</source>
        <comment>device.event.lost_steps</comment>
        <translation>丢步</translation>
    </message>
    <message>
        <source>reset</source>
        <comment>device.event.reset</comment>
        <translation>已复位</translation>
    </message>
    <message>
        <source>test ended</source>
        <comment>device.event.test_ended</comment>
        <translation>测试结束</translation>
    </message>
    <message>
        <source>test tripped its envelope</source>
        <comment>device.event.test_tripped</comment>
        <translation>测试超出安全包络</translation>
    </message>
    <message>
        <source>test aborted</source>
        <comment>device.event.test_aborted</comment>
        <translation>测试已中止</translation>
    </message>
    <message>
        <source>gains changed</source>
        <comment>device.event.gains_changed</comment>
        <translation>增益已更改</translation>
    </message>
    <message>
        <source>path started</source>
        <comment>device.event.path_started</comment>
        <translation>路径开始</translation>
    </message>
    <message>
        <source>path segment done</source>
        <comment>device.event.path_segment_done</comment>
        <translation>路径段完成</translation>
    </message>
    <message>
        <source>path underrun</source>
        <comment>device.event.path_underrun</comment>
        <translation>路径队列欠载</translation>
    </message>
    <message>
        <source>path done</source>
        <comment>device.event.path_done</comment>
        <translation>路径完成</translation>
    </message>
    <message>
        <source>path held</source>
        <comment>device.event.path_held</comment>
        <translation>路径已暂停</translation>
    </message>
    <message>
        <source>path aborted</source>
        <comment>device.event.path_aborted</comment>
        <translation>路径已中止</translation>
    </message>
    <message>
        <source>compensation changed</source>
        <comment>device.event.comp_changed</comment>
        <translation>补偿已更改</translation>
    </message>
    <message>
        <source>unknown event</source>
        <comment>device.event.unknown</comment>
        <translation>未知事件</translation>
    </message>
    <message>
        <source>idle</source>
        <comment>path.state.idle</comment>
        <translation>空闲</translation>
    </message>
    <message>
        <source>filling</source>
        <comment>path.state.filling</comment>
        <translation>正在装入</translation>
    </message>
    <message>
        <source>running</source>
        <comment>path.state.running</comment>
        <translation>运行中</translation>
    </message>
    <message>
        <source>waiting for segments</source>
        <comment>path.state.starved</comment>
        <translation>等待路径段</translation>
    </message>
    <message>
        <source>holding</source>
        <comment>path.state.holding</comment>
        <translation>正在暂停</translation>
    </message>
    <message>
        <source>held</source>
        <comment>path.state.held</comment>
        <translation>已暂停</translation>
    </message>
    <message>
        <source>done</source>
        <comment>path.state.done</comment>
        <translation>已完成</translation>
    </message>
    <message>
        <source>aborted</source>
        <comment>path.state.aborted</comment>
        <translation>已中止</translation>
    </message>
    <message>
        <source>no reason given</source>
        <comment>path.reason.none</comment>
        <translation>未说明原因</translation>
    </message>
    <message>
        <source>paused from BenchPilot</source>
        <comment>path.reason.host_hold</comment>
        <translation>由 BenchPilot 暂停</translation>
    </message>
    <message>
        <source>the instrument heard nothing from BenchPilot for a second</source>
        <comment>path.reason.host_silent</comment>
        <translation>仪器一秒内未收到 BenchPilot 的任何消息</translation>
    </message>
    <message>
        <source>a stop</source>
        <comment>path.reason.stop</comment>
        <translation>停止命令</translation>
    </message>
    <message>
        <source>the E-stop</source>
        <comment>path.reason.estop</comment>
        <translation>急停</translation>
    </message>
    <message>
        <source>a limit switch</source>
        <comment>path.reason.limit_switch</comment>
        <translation>限位开关</translation>
    </message>
    <message>
        <source>a new connection to the instrument</source>
        <comment>path.reason.new_session</comment>
        <translation>仪器建立了新的连接</translation>
    </message>
    <message>
        <source>abort</source>
        <comment>path.reason.cleared</comment>
        <translation>中止</translation>
    </message>
    <message>
        <source>link</source>
        <comment>log.kind.link</comment>
        <translation>连接</translation>
    </message>
    <message>
        <source>link error</source>
        <comment>log.kind.link_error</comment>
        <translation>连接错误</translation>
    </message>
    <message>
        <source>refused</source>
        <comment>log.kind.refused</comment>
        <translation>被拒绝</translation>
    </message>
    <message>
        <source>disconnected</source>
        <comment>link.state.disconnected</comment>
        <translation>未连接</translation>
    </message>
    <message>
        <source>connecting</source>
        <comment>link.state.connecting</comment>
        <translation>正在连接</translation>
    </message>
    <message>
        <source>identified</source>
        <comment>link.state.identified</comment>
        <translation>已识别</translation>
    </message>
    <message>
        <source>ready</source>
        <comment>link.state.ready</comment>
        <translation>就绪</translation>
    </message>
    <message>
        <source>link lost</source>
        <comment>link.state.lost</comment>
        <translation>连接中断</translation>
    </message>
    <message>
        <source>%1 has control of the bench: take it back first</source>
        <comment>request.bench_held</comment>
        <translation>%1 正在控制工作台：请先收回控制权</translation>
    </message>
    <message>
        <source>this instrument has no alarm lock to release: home it instead</source>
        <comment>request.no_alarm_lock</comment>
        <translation>该仪器没有可解除的报警锁定：请改为回零。</translation>
    </message>
    <message>
        <source>%1: the device clock started again; its plots go on after a gap</source>
        <comment>telemetry.clock_restarted</comment>
        <translation>%1：设备时钟已重新开始，其曲线在间断之后继续</translation>
    </message>
    <message>
        <source>no history recorded yet: connect an instrument first</source>
        <comment>telemetry.history_empty</comment>
        <translation>尚未记录任何历史：请先连接仪器</translation>
    </message>
    <message>
        <source>compensation refused</source>
        <comment>device.error.comp_invalid</comment>
        <translation>补偿被拒绝</translation>
    </message>
    <message>
        <source>compensation upload out of order</source>
        <comment>device.error.comp_sequence</comment>
        <translation>补偿上传顺序错误</translation>
    </message>
    <message>
        <source>no compensation</source>
        <comment>device.error.comp_missing</comment>
        <translation>无补偿</translation>
    </message>
    <message>
        <source>no whole answer from %1 within %2, only damaged frames (%3): a noisy line or a wrong baud rate; check the cable and the baud rate</source>
        <comment>link.only_damaged</comment>
        <translation>%2 内未收到 %1 的完整应答，只收到损坏的帧（%3 个）：线路噪声过大或波特率错误；请检查电缆和波特率</translation>
    </message>
    <message>
        <source>%1 went silent while connecting: only damaged frames came (%2), then nothing for %3; check power and cable</source>
        <comment>link.went_silent</comment>
        <translation>%1 在连接过程中停止应答：只收到损坏的帧（%2 个），之后 %3 内没有任何数据；请检查电源和电缆</translation>
    </message>
    <message>
        <source>cannot open %1: another program has it open (%2)</source>
        <comment>link.port_busy</comment>
        <translation>无法打开 %1：另一个程序正在使用它（%2）</translation>
    </message>
    <message>
        <source>cannot open %1: only members of the group %2 may use it, and this login is not one. Add yourself once with &quot;sudo usermod -aG %2 $USER&quot;, then log out and in again</source>
        <comment>link.port_group</comment>
        <translation>无法打开 %1：只有 %2 组的成员才能使用它，而当前登录会话不在该组中。请执行一次 &quot;sudo usermod -aG %2 $USER&quot;，然后注销并重新登录</translation>
    </message>
    <message>
        <source>cannot open %1: you may not read and write it (%2); ask the computer&apos;s administrator</source>
        <comment>link.port_denied</comment>
        <translation>无法打开 %1：您没有读写它的权限（%2）；请联系这台计算机的管理员</translation>
    </message>
</context>
<context>
    <name>ui::words::Durations</name>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>%1 min %2 s</source>
        <translation>%1 min %2 s</translation>
    </message>
    <message>
        <source>%1 h %2 min</source>
        <translation>%1 h %2 min</translation>
    </message>
</context>
<context>
    <name>ui::words::EventWords</name>
    <message>
        <source>already there: nothing moved</source>
        <comment>device.why.already_there</comment>
        <translation>已在目标位置：未运动</translation>
    </message>
    <message>
        <source>arrived outside the in-position window</source>
        <comment>device.why.outside_window</comment>
        <translation>已到达，但在到位窗口之外</translation>
    </message>
    <message>
        <source>axis %1 hit its home switch</source>
        <comment>device.why.home_switch</comment>
        <translation>%1 轴碰到零位开关</translation>
    </message>
    <message>
        <source>axis %1 hit its limit switch</source>
        <comment>device.why.limit_switch</comment>
        <translation>%1 轴碰到限位开关</translation>
    </message>
    <message>
        <source>axis %1 found no home switch over its whole travel</source>
        <comment>device.why.home_switch_not_found</comment>
        <translation>%1 轴在整个行程内未找到零位开关</translation>
    </message>
    <message>
        <source>all motion halted</source>
        <comment>device.why.all_halted</comment>
        <translation>所有运动已停止</translation>
    </message>
    <message>
        <source>axis %1 heard no jog for %2, so it stopped</source>
        <comment>device.why.jog_not_refreshed</comment>
        <translation>%1 轴在 %2 内未收到点动指令，已停止</translation>
    </message>
    <message>
        <source>stopped on request</source>
        <comment>device.why.stop_request</comment>
        <translation>应请求停止</translation>
    </message>
    <message>
        <source>stopped with the axis it moves with</source>
        <comment>device.why.with_coupled_axis</comment>
        <translation>随联动轴一起停止</translation>
    </message>
    <message>
        <source>homing cancelled: another axis found no home switch</source>
        <comment>device.why.homing_other_failed</comment>
        <translation>回零已取消：另一轴未找到零位开关</translation>
    </message>
    <message>
        <source>homing cancelled: an axis homed before this one did not reach home</source>
        <comment>device.why.homing_earlier_failed</comment>
        <translation>回零已取消：先于此轴回零的轴未到达零位</translation>
    </message>
    <message>
        <source>homing stopped before this axis&apos; turn</source>
        <comment>device.why.homing_stopped</comment>
        <translation>轮到此轴之前回零已停止</translation>
    </message>
    <message>
        <source>cancelled: the move it waited for was stopped</source>
        <comment>device.why.waited_move_stopped</comment>
        <translation>已取消：所等待的运动被停止</translation>
    </message>
    <message>
        <source>cancelled: a switch stopped the move it waited for</source>
        <comment>device.why.waited_move_hit_switch</comment>
        <translation>已取消：所等待的运动被开关停止</translation>
    </message>
    <message>
        <source>axis %1&apos;s encoder is %2 off the command</source>
        <comment>device.why.off_command</comment>
        <translation>%1 轴编码器偏离指令位置 %2</translation>
    </message>
    <message>
        <source>E-stop and faults cleared</source>
        <comment>device.why.cleared</comment>
        <translation>急停和故障已清除</translation>
    </message>
    <message>
        <source>axis %1 %2 settled after %3</source>
        <comment>device.why.test_settled</comment>
        <translation>%1 轴%2在 %3 后稳定</translation>
    </message>
    <message>
        <source>axis %1 %2 completed in %3</source>
        <comment>device.why.test_completed</comment>
        <translation>%1 轴%2完成，用时 %3</translation>
    </message>
    <message>
        <source>axis %1 %2 stopped after %5: its excursion reached %4, past the limit of %3; the axis stopped at %6</source>
        <comment>device.why.test_excursion</comment>
        <translation>%1 轴%2在 %5 后停止：偏移达到 %4，超过限值 %3；轴停在 %6</translation>
    </message>
    <message>
        <source>axis %1 %2 stopped after %5: its following error reached %4, past the limit of %3; the axis stopped at %6</source>
        <comment>device.why.test_following_error</comment>
        <translation>%1 轴%2在 %5 后停止：跟随误差达到 %4，超过限值 %3；轴停在 %6</translation>
    </message>
    <message>
        <source>axis %1 %2 stopped at its time limit of %3; the axis stopped at %4</source>
        <comment>device.why.test_duration</comment>
        <translation>%1 轴%2达到时间限值 %3 而停止；轴停在 %4</translation>
    </message>
    <message>
        <source>axis %1 %2 stopped on request</source>
        <comment>device.why.test_on_request</comment>
        <translation>%1 轴%2应请求停止</translation>
    </message>
    <message>
        <source>axis %1 %2 ended by the E-stop</source>
        <comment>device.why.test_estop</comment>
        <translation>%1 轴%2因急停结束</translation>
    </message>
    <message>
        <source>axis %1 %2 ended: nothing came from BenchPilot for %3, so the axis stopped</source>
        <comment>device.why.test_host_silent</comment>
        <translation>%1 轴%2结束：%3 内未收到 BenchPilot 的任何消息，轴已停止</translation>
    </message>
    <message>
        <source>axis %1 %2 ended by a fault</source>
        <comment>device.why.test_fault</comment>
        <translation>%1 轴%2因故障结束</translation>
    </message>
    <message>
        <source>axis %1 gains per control period: kp %2, ki %3, kd %4</source>
        <comment>device.why.gains_set</comment>
        <translation>%1 轴每控制周期增益：kp %2，ki %3，kd %4</translation>
    </message>
    <message>
        <source>axis %1 gains per control period: kp %2, ki %3, kd %4, kept as its power-up gains</source>
        <comment>device.why.gains_set_kept</comment>
        <translation>%1 轴每控制周期增益：kp %2，ki %3，kd %4，已保存为上电增益</translation>
    </message>
    <message>
        <source>axis %1 is back on the gains in force before the set that tripped the test: kp %2, ki %3, kd %4</source>
        <comment>device.why.gains_fell_back</comment>
        <translation>%1 轴已恢复为触发测试的那组增益之前的增益：kp %2，ki %3，kd %4</translation>
    </message>
    <message numerus="yes">
        <source>axis %1: a compensation table of %Ln points installed, not yet enabled</source>
        <comment>device.why.comp_installed_table</comment>
        <translation>
            <numerusform>%1 轴：已安装 %Ln 点补偿表，尚未启用</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>axis %1: a compensation table of %Ln points per direction installed, not yet enabled</source>
        <comment>device.why.comp_installed_table_per_direction</comment>
        <translation>
            <numerusform>%1 轴：已安装每方向 %Ln 点的补偿表，尚未启用</numerusform>
        </translation>
    </message>
    <message>
        <source>axis %1: a compensation polynomial of order %2 over %3 to %4 installed, not yet enabled</source>
        <comment>device.why.comp_installed_polynomial</comment>
        <translation>%1 轴：已安装 %2 阶补偿多项式（%3 至 %4），尚未启用</translation>
    </message>
    <message>
        <source>axis %1: compensation enabled</source>
        <comment>device.why.comp_enabled</comment>
        <translation>%1 轴：补偿已启用</translation>
    </message>
    <message>
        <source>axis %1: compensation enabled and kept for power-up</source>
        <comment>device.why.comp_enabled_kept</comment>
        <translation>%1 轴：补偿已启用，并保存为上电设置</translation>
    </message>
    <message>
        <source>axis %1: compensation disabled</source>
        <comment>device.why.comp_disabled</comment>
        <translation>%1 轴：补偿已停用</translation>
    </message>
    <message>
        <source>axis %1: compensation disabled, and kept so for power-up</source>
        <comment>device.why.comp_disabled_kept</comment>
        <translation>%1 轴：补偿已停用，并保存为上电设置</translation>
    </message>
    <message>
        <source>the queue ran dry: at rest until more segments arrive</source>
        <comment>device.why.path_underrun</comment>
        <translation>队列已空：静止等待更多段</translation>
    </message>
    <message>
        <source>held: %1</source>
        <comment>device.why.path_held</comment>
        <translation>已暂停：%1</translation>
    </message>
    <message>
        <source>ended: %1</source>
        <comment>device.why.path_ended</comment>
        <translation>已结束：%1</translation>
    </message>
</context>
<context>
    <name>ui::words::FileWords</name>
    <message>
        <source>warning: %1</source>
        <translation>警告：%1</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <comment>file.unreadable</comment>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <source>cannot open %1: %2</source>
        <comment>file.cannot_open</comment>
        <translation>无法打开 %1：%2</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <comment>file.cannot_read</comment>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <comment>file.cannot_write</comment>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>%1 is %2 MiB, more than the %3 MiB a BenchPilot file may be</source>
        <comment>file.too_large</comment>
        <translation>%1 大小为 %2 MiB，超过 BenchPilot 文件上限 %3 MiB</translation>
    </message>
    <message>
        <source>cannot make the folder %1</source>
        <comment>file.cannot_make_folder</comment>
        <translation>无法创建文件夹 %1</translation>
    </message>
    <message>
        <source>not valid JSON: %1</source>
        <comment>file.json_syntax</comment>
        <translation>不是有效的 JSON：%1</translation>
    </message>
    <message>
        <source>%1</source>
        <comment>file.json_field</comment>
        <translation>%1</translation>
    </message>
    <message>
        <source>a quoted field is not closed</source>
        <comment>file.csv.unterminated_quote</comment>
        <translation>带引号的字段没有闭合</translation>
    </message>
    <message>
        <source>text after a closing quote</source>
        <comment>file.csv.text_after_quote</comment>
        <translation>闭合引号之后还有文字</translation>
    </message>
    <message>
        <source>the file is separated by semicolons; BenchPilot reads commas and &apos;.&apos; as the decimal point</source>
        <comment>file.csv.semicolons</comment>
        <translation>文件以分号分隔；BenchPilot 读取逗号分隔、以“.”为小数点的文件</translation>
    </message>
    <message>
        <source>the text is larger than %1 MiB</source>
        <comment>file.json.too_large</comment>
        <translation>文本超过 %1 MiB</translation>
    </message>
    <message>
        <source>unexpected text after the end of the document</source>
        <comment>file.json.text_after_end</comment>
        <translation>文档结束之后还有多余的文字</translation>
    </message>
    <message>
        <source>nested deeper than %1 levels</source>
        <comment>file.json.too_deep</comment>
        <translation>嵌套超过 %1 层</translation>
    </message>
    <message>
        <source>comments are not allowed in JSON</source>
        <comment>file.json.comment</comment>
        <translation>JSON 中不允许注释</translation>
    </message>
    <message>
        <source>expected a value, found %1</source>
        <comment>file.json.expected_value</comment>
        <translation>此处应为一个值，却是%1</translation>
    </message>
    <message>
        <source>a number may not have leading zeros</source>
        <comment>file.json.leading_zero</comment>
        <translation>数字不能有前导零</translation>
    </message>
    <message>
        <source>expected a digit, found %1</source>
        <comment>file.json.expected_digit</comment>
        <translation>此处应为数字，却是%1</translation>
    </message>
    <message>
        <source>expected a digit after the decimal point, found %1</source>
        <comment>file.json.expected_fraction_digit</comment>
        <translation>小数点后应为数字，却是%1</translation>
    </message>
    <message>
        <source>expected a digit in the exponent, found %1</source>
        <comment>file.json.expected_exponent_digit</comment>
        <translation>指数中应为数字，却是%1</translation>
    </message>
    <message>
        <source>the number is too large for a double</source>
        <comment>file.json.number_too_large</comment>
        <translation>数字太大，超出双精度范围</translation>
    </message>
    <message>
        <source>malformed number</source>
        <comment>file.json.malformed_number</comment>
        <translation>数字格式错误</translation>
    </message>
    <message>
        <source>expected four hex digits after \u</source>
        <comment>file.json.bad_unicode_escape</comment>
        <translation>\u 之后应为四位十六进制数字</translation>
    </message>
    <message>
        <source>invalid UTF-8 byte %1</source>
        <comment>file.json.invalid_utf8_byte</comment>
        <translation>无效的 UTF-8 字节 %1</translation>
    </message>
    <message>
        <source>truncated UTF-8 character</source>
        <comment>file.json.truncated_utf8</comment>
        <translation>UTF-8 字符不完整</translation>
    </message>
    <message>
        <source>invalid UTF-8 sequence</source>
        <comment>file.json.invalid_utf8</comment>
        <translation>无效的 UTF-8 序列</translation>
    </message>
    <message>
        <source>unterminated string</source>
        <comment>file.json.unterminated_string</comment>
        <translation>字符串没有结束引号</translation>
    </message>
    <message>
        <source>unterminated string (a line break inside quotes)</source>
        <comment>file.json.line_break_in_string</comment>
        <translation>字符串没有结束引号（引号内有换行）</translation>
    </message>
    <message>
        <source>a control character inside a string must be escaped</source>
        <comment>file.json.control_character</comment>
        <translation>字符串中的控制字符必须转义</translation>
    </message>
    <message>
        <source>a \u escape of a high surrogate must be followed by a low surrogate</source>
        <comment>file.json.lone_high_surrogate</comment>
        <translation>高代理项的 \u 转义之后必须跟低代理项</translation>
    </message>
    <message>
        <source>a lone low surrogate in a \u escape</source>
        <comment>file.json.lone_low_surrogate</comment>
        <translation>\u 转义中出现孤立的低代理项</translation>
    </message>
    <message>
        <source>unknown escape \%1</source>
        <comment>file.json.unknown_escape</comment>
        <translation>未知的转义 \%1</translation>
    </message>
    <message>
        <source>a trailing comma before &apos;%1&apos; is not allowed</source>
        <comment>file.json.trailing_comma</comment>
        <translation>“%1”之前不允许有多余的逗号</translation>
    </message>
    <message>
        <source>expected &apos;,&apos; or &apos;]&apos; in an array, found %1</source>
        <comment>file.json.expected_array_comma</comment>
        <translation>数组中此处应为“,”或“]”，却是%1</translation>
    </message>
    <message>
        <source>expected a quoted member name, found %1</source>
        <comment>file.json.expected_member_name</comment>
        <translation>此处应为带引号的成员名，却是%1</translation>
    </message>
    <message>
        <source>expected &apos;:&apos; after the member name &quot;%1&quot;, found %2</source>
        <comment>file.json.expected_colon</comment>
        <translation>成员名“%1”之后应为“:”，却是%2</translation>
    </message>
    <message>
        <source>expected &apos;,&apos; or &apos;}&apos; in an object, found %1</source>
        <comment>file.json.expected_object_comma</comment>
        <translation>对象中此处应为“,”或“}”，却是%1</translation>
    </message>
    <message>
        <source>the member &quot;%1&quot; appears twice</source>
        <comment>file.json.duplicate_member</comment>
        <translation>成员“%1”出现了两次</translation>
    </message>
    <message>
        <source>the end of the text</source>
        <comment>file.json.found_end</comment>
        <translation>文本结尾</translation>
    </message>
    <message>
        <source>a byte %1</source>
        <comment>file.json.found_byte</comment>
        <translation>字节 %1</translation>
    </message>
    <message>
        <source>&apos;%1&apos;</source>
        <comment>file.json.found_char</comment>
        <translation>“%1”</translation>
    </message>
    <message>
        <source>is missing</source>
        <comment>file.json.missing</comment>
        <translation>缺失</translation>
    </message>
    <message>
        <source>must be %1, not %2</source>
        <comment>file.json.wrong_type</comment>
        <translation>必须是%1，而不是%2</translation>
    </message>
    <message>
        <source>must be a number or null, not %1</source>
        <comment>file.json.number_or_null</comment>
        <translation>必须是数字或 null，而不是%1</translation>
    </message>
    <message>
        <source>must be from %1 to %2 (got %3)</source>
        <comment>file.json.out_of_range</comment>
        <translation>必须在 %1 到 %2 之间（当前为 %3）</translation>
    </message>
    <message>
        <source>must be at least %1 (got %2)</source>
        <comment>file.json.below_min</comment>
        <translation>必须不小于 %1（当前为 %2）</translation>
    </message>
    <message>
        <source>must be at most %1 (got %2)</source>
        <comment>file.json.above_max</comment>
        <translation>必须不大于 %1（当前为 %2）</translation>
    </message>
    <message>
        <source>must be a whole number (got %1)</source>
        <comment>file.json.not_whole</comment>
        <translation>必须是整数（当前为 %1）</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not one of %2</source>
        <comment>file.json.not_one_of</comment>
        <translation>“%1”不是以下之一：%2</translation>
    </message>
    <message>
        <source>unknown field</source>
        <comment>file.json.unknown_field</comment>
        <translation>未知字段</translation>
    </message>
    <message>
        <source>unknown field; did you mean &quot;%1&quot;?</source>
        <comment>file.json.unknown_field_suggest</comment>
        <translation>未知字段；是否指“%1”？</translation>
    </message>
    <message>
        <source>must be an array of %1 numbers</source>
        <comment>file.json.array_of_numbers</comment>
        <translation>必须是含 %1 个数字的数组</translation>
    </message>
    <message>
        <source>the document must be an object, not %1</source>
        <comment>file.json.document_not_object</comment>
        <translation>文档必须是对象，而不是%1</translation>
    </message>
    <message>
        <source>must name the file&apos;s kind: &quot;schema&quot;: &quot;%1&quot;</source>
        <comment>file.json.schema_missing</comment>
        <translation>必须注明文件类型：&quot;schema&quot;: &quot;%1&quot;</translation>
    </message>
    <message>
        <source>is &quot;%1&quot;, expected &quot;%2&quot;</source>
        <comment>file.json.schema_wrong</comment>
        <translation>为“%1”，应为“%2”</translation>
    </message>
    <message>
        <source>must be a whole number from 1</source>
        <comment>file.json.version_invalid</comment>
        <translation>必须是从 1 开始的整数</translation>
    </message>
    <message>
        <source>is %1: written by a newer BenchPilot (this one reads up to %2)</source>
        <comment>file.json.version_newer</comment>
        <translation>为 %1：由更新版本的 BenchPilot 写入（本版本最多读取 %2）</translation>
    </message>
    <message>
        <source>must be 16 lower-case hex digits</source>
        <comment>file.log.bad_fingerprint</comment>
        <translation>必须是 16 位小写十六进制数字</translation>
    </message>
    <message>
        <source>the log is empty: it has no header line</source>
        <comment>file.log.empty</comment>
        <translation>日志为空：没有表头行</translation>
    </message>
    <message>
        <source>the log has no &quot;run&quot; header</source>
        <comment>file.log.no_header</comment>
        <translation>日志没有“run”表头</translation>
    </message>
    <message>
        <source>the log must begin with its &quot;run&quot; header</source>
        <comment>file.log.no_header_first</comment>
        <translation>日志必须以“run”表头开始</translation>
    </message>
    <message>
        <source>a second run header: one log holds one run and its resumptions</source>
        <comment>file.log.second_header</comment>
        <translation>出现第二个运行表头：一个日志只记录一次运行及其续行</translation>
    </message>
    <message>
        <source>op %1 is beyond the %2 ops of the header</source>
        <comment>file.log.op_beyond</comment>
        <translation>操作 %1 超出表头所列的 %2 个操作</translation>
    </message>
    <message>
        <source>op %1 starts again after it was done: the log is not trustworthy</source>
        <comment>file.log.op_restarted</comment>
        <translation>操作 %1 完成后又重新开始：该日志不可信</translation>
    </message>
    <message>
        <source>a pump line for op %1, which has not started</source>
        <comment>file.log.pump_before_start</comment>
        <translation>操作 %1 尚未开始，却有其泵动作记录</translation>
    </message>
    <message>
        <source>op %1 is done but was not under way</source>
        <comment>file.log.done_not_started</comment>
        <translation>操作 %1 标记为完成，但并未在进行中</translation>
    </message>
    <message>
        <source>only an interrupted op can be skipped (op %1)</source>
        <comment>file.log.skip_not_interrupted</comment>
        <translation>只有中断的操作才能跳过（操作 %1）</translation>
    </message>
    <message>
        <source>cannot open the run log %1: %2</source>
        <comment>file.log.cannot_open</comment>
        <translation>无法打开运行日志 %1：%2</translation>
    </message>
    <message>
        <source>cannot write the run log %1: %2</source>
        <comment>file.log.cannot_write</comment>
        <translation>无法写入运行日志 %1：%2</translation>
    </message>
    <message>
        <source>cannot sync the run log %1 to disk: %2</source>
        <comment>file.log.cannot_sync</comment>
        <translation>无法将运行日志 %1 同步到磁盘：%2</translation>
    </message>
    <message>
        <source>the run log is not open</source>
        <comment>file.log.not_open</comment>
        <translation>运行日志未打开</translation>
    </message>
    <message>
        <source>null</source>
        <comment>json.type.null</comment>
        <translation>null</translation>
    </message>
    <message>
        <source>true or false</source>
        <comment>json.type.bool</comment>
        <translation>true 或 false</translation>
    </message>
    <message>
        <source>a number</source>
        <comment>json.type.number</comment>
        <translation>数字</translation>
    </message>
    <message>
        <source>a string</source>
        <comment>json.type.string</comment>
        <translation>字符串</translation>
    </message>
    <message>
        <source>an array</source>
        <comment>json.type.array</comment>
        <translation>数组</translation>
    </message>
    <message>
        <source>an object</source>
        <comment>json.type.object</comment>
        <translation>对象</translation>
    </message>
    <message>
        <source>must be 64 lower-case hex digits (the image&apos;s SHA-256)</source>
        <comment>file.log.bad_sha256</comment>
        <translation>必须是 64 位小写十六进制数字（图像的 SHA-256）</translation>
    </message>
    <message>
        <source>a tile&apos;s &quot;image&quot; and &quot;sha256&quot; come together: one without the other is not a line this program wrote</source>
        <comment>file.log.image_without_sha256</comment>
        <translation>图块的 &quot;image&quot; 和 &quot;sha256&quot; 成对出现：缺少其中之一的行不是本程序写的</translation>
    </message>
    <message>
        <source>must name a file in the run&apos;s folder (no folder, no &quot;..&quot;)</source>
        <comment>file.log.bad_image_name</comment>
        <translation>必须是运行文件夹中的文件名（不含文件夹，不含 &quot;..&quot;）</translation>
    </message>
</context>
<context>
    <name>ui::words::GrblBackendWords</name>
    <message>
        <source>no answer from %1 within %2: check power, cable and baud rate (GRBL boards usually run at 115200 Bd)</source>
        <comment>grbl.connect.no_answer</comment>
        <translation>%1 在 %2 内无应答：请检查电源、线缆和波特率（GRBL 控制板通常为 115200 Bd）</translation>
    </message>
    <message>
        <source>%1 sent %2 bytes but no GRBL line within %3: a wrong baud rate, or not a GRBL controller</source>
        <comment>grbl.connect.no_grbl_line</comment>
        <translation>%1 在 %3 内发送了 %2 字节，但没有一行 GRBL 消息：可能波特率错误，或不是 GRBL 控制器</translation>
    </message>
    <message>
        <source>%1 answers like GRBL but never acknowledged a line within %2: it may be busy (in a critical alarm it hears nothing but a reset)</source>
        <comment>grbl.connect.never_acknowledged</comment>
        <translation>%1 的应答像 GRBL，但在 %2 内从未确认过任何一行：它可能正忙（处于严重报警时，它只响应复位）</translation>
    </message>
    <message>
        <source>%1 stopped answering while it was being identified ($I, $$, $#)</source>
        <comment>grbl.connect.identify_silent</comment>
        <translation>%1 在识别过程中（$I、$$、$#）停止了应答</translation>
    </message>
    <message>
        <source>%1 was not answered: %2</source>
        <comment>grbl.identify.not_answered</comment>
        <translation>%1 未获应答：%2</translation>
    </message>
    <message>
        <source>the controller refused %1 with error:%2 (%3)</source>
        <comment>grbl.identify.refused</comment>
        <translation>控制器以 error:%2 拒绝了 %1（%3）</translation>
    </message>
    <message>
        <source>the controller&apos;s settings ($$) do not give its limits: %1 (%2 problems in all)</source>
        <comment>grbl.identify.no_limits</comment>
        <translation>控制器的设置（$$）未给出其限值：%1（共 %2 个问题）</translation>
    </message>
    <message>
        <source>the controller reports positions in inches ($13=1) and the machine profile refuses inch reports: set $13=0 on the controller, or &quot;inch_reports&quot;: &quot;convert&quot; in the profile</source>
        <comment>grbl.identify.inches_refused</comment>
        <translation>控制器以英寸报告位置（$13=1），而机器配置不接受英寸报告：请在控制器上设置 $13=0，或在配置文件中设置 &quot;inch_reports&quot;: &quot;convert&quot;</translation>
    </message>
    <message>
        <source>the machine profile drives axis %1 with GRBL axis %2, but this controller has axes %3</source>
        <comment>grbl.identify.axis_missing</comment>
        <translation>机器配置用 GRBL 的 %2 轴驱动 %1 轴，但该控制器只有 %3 轴</translation>
    </message>
    <message>
        <source>the machine profile drives the pump with GRBL axis %1, but this controller has axes %2</source>
        <comment>grbl.identify.pump_axis_missing</comment>
        <translation>机器配置用 GRBL 的 %1 轴驱动泵，但该控制器只有 %2 轴</translation>
    </message>
    <message>
        <source>the controller stopped answering: no status report for %1</source>
        <comment>grbl.silent</comment>
        <translation>控制器停止了应答：%1 内没有状态报告</translation>
    </message>
    <message>
        <source>no status report for %1 (%2 unreadable lines: a wrong baud rate or noise?)</source>
        <comment>grbl.silent_with_noise</comment>
        <translation>%1 内没有状态报告（%2 行无法解读：波特率错误或有干扰？）</translation>
    </message>
    <message>
        <source>the controller reset by itself</source>
        <comment>grbl.reset_by_itself</comment>
        <translation>控制器自行复位了</translation>
    </message>
    <message>
        <source>a reset flushed it</source>
        <comment>grbl.reset_flushed</comment>
        <translation>被复位清除</translation>
    </message>
    <message>
        <source>stop: the controller did not come to rest and reset within %1</source>
        <comment>grbl.stop_timeout</comment>
        <translation>停止：控制器未在 %1 内停稳并复位</translation>
    </message>
    <message>
        <source>stop overtaken by the E-stop</source>
        <comment>grbl.stop_overtaken_by_estop</comment>
        <translation>停止被急停取代</translation>
    </message>
    <message>
        <source>%1: the line &quot;%2&quot; cannot be sent</source>
        <comment>grbl.line_not_sent</comment>
        <translation>%1：无法发送“%2”这一行</translation>
    </message>
    <message>
        <source>%1: the E-stop is latched: reset it first</source>
        <comment>grbl.estop_latched</comment>
        <translation>%1：急停已锁定：请先复位</translation>
    </message>
    <message>
        <source>home: GRBL homes one axis or all of them, not %1</source>
        <comment>grbl.home_one_or_all</comment>
        <translation>回零：GRBL 只能对单个轴或全部轴回零，不能对 %1 回零</translation>
    </message>
    <message>
        <source>set zero: wait until the instrument is still</source>
        <comment>grbl.set_zero_while_moving</comment>
        <translation>设零点：请等仪器静止后再操作</translation>
    </message>
    <message>
        <source>set zero: no such axis</source>
        <comment>grbl.set_zero_no_axis</comment>
        <translation>设零点：没有该轴</translation>
    </message>
    <message>
        <source>GRBL enforces its machine travel ($130–$132) as its soft limits; other limits cannot be set from here</source>
        <comment>grbl.soft_limits_fixed</comment>
        <translation>GRBL 以其机床行程（$130–$132）作为软限位；无法在此设置其他限位</translation>
    </message>
    <message>
        <source>move: the controller is in alarm (its position is not trusted): home it, or unlock it on your word</source>
        <comment>grbl.move_in_alarm</comment>
        <translation>移动：控制器处于报警状态（其位置不可信）：请回零，或在确认后解锁</translation>
    </message>
    <message>
        <source>move: axis %1 has no established position: home it, or take the present position as home (Set home here, `zero`) first</source>
        <comment>grbl.move_not_established</comment>
        <translation>移动：%1 轴尚无确定的位置：请先回零，或将当前位置作为零位（“设此处为原点”，`zero`）</translation>
    </message>
    <message>
        <source>this instrument has no trigger output: the machine profile names none</source>
        <comment>grbl.no_trigger_output</comment>
        <translation>该仪器没有触发输出：机器配置未指定</translation>
    </message>
    <message>
        <source>trigger: %1 is not a pulse width</source>
        <comment>grbl.trigger_bad_width</comment>
        <translation>触发：%1 不是有效的脉冲宽度</translation>
    </message>
    <message>
        <source>E-stop: feed hold and soft reset; if it was moving, the controller lost its position</source>
        <comment>grbl.event.estop</comment>
        <translation>急停：进给保持并软复位；若当时正在运动，控制器已丢失位置</translation>
    </message>
    <message>
        <source>E-stop latch cleared</source>
        <comment>grbl.event.estop_cleared</comment>
        <translation>急停锁定已解除</translation>
    </message>
    <message>
        <source>a path is already running</source>
        <comment>grbl.path.already_running</comment>
        <translation>已有路径正在运行</translation>
    </message>
    <message>
        <source>no path begun, or it has ended</source>
        <comment>grbl.path.not_begun</comment>
        <translation>没有已开始的路径，或路径已结束</translation>
    </message>
    <message>
        <source>segment %1 expected, %2 sent</source>
        <comment>grbl.path.out_of_sequence</comment>
        <translation>应为第 %1 段，实际发送了第 %2 段</translation>
    </message>
    <message>
        <source>the path window is full (room for %1 more segments)</source>
        <comment>grbl.path.window_full</comment>
        <translation>路径窗口已满（还能容纳 %1 段）</translation>
    </message>
    <message>
        <source>segment %1 asks Z to follow the path: GRBL cannot</source>
        <comment>grbl.path.z_in_path</comment>
        <translation>第 %1 段要求 Z 轴随路径运动：GRBL 无法做到</translation>
    </message>
    <message>
        <source>no answer from %1 within %2, neither to a GRBL status query nor to a BenchPilot HELLO: check power, cable and baud rate</source>
        <comment>grbl.probe.no_answer</comment>
        <translation>%1 在 %2 内无应答（对 GRBL 状态查询和 BenchPilot HELLO 均无应答）：请检查电源、线缆和波特率</translation>
    </message>
    <message>
        <source>%1 sent %2 bytes within %3 that are neither GRBL lines nor BenchPilot frames: a wrong baud rate, or another kind of device</source>
        <comment>grbl.probe.unreadable</comment>
        <translation>%1 在 %3 内发送了 %2 字节，既不是 GRBL 消息行，也不是 BenchPilot 帧：可能波特率错误，或是其他类型的设备</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <comment>grbl.probe.found_grbl</comment>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>a GRBL controller</source>
        <comment>grbl.probe.found_grbl_unnamed</comment>
        <translation>GRBL 控制器</translation>
    </message>
    <message>
        <source>BenchPilot protocol %1 (%2)</source>
        <comment>grbl.probe.found_benchpilot</comment>
        <translation>BenchPilot 协议 %1（%2）</translation>
    </message>
    <message>
        <source>must be one upper-case axis letter (got &quot;%1&quot;)</source>
        <comment>grbl.profile.axis_letter</comment>
        <translation>必须是一个大写轴字母（当前为“%1”）</translation>
    </message>
    <message>
        <source>the %1 has axes %2 in that order (got &quot;%3&quot;)</source>
        <comment>grbl.profile.axes_order</comment>
        <translation>%1的轴依次为 %2（当前为“%3”）</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a GRBL axis (X, Y, Z, A, B, C)</source>
        <comment>grbl.profile.not_grbl_axis</comment>
        <translation>“%1”不是 GRBL 轴（X、Y、Z、A、B、C）</translation>
    </message>
    <message>
        <source>GRBL axis %1 is already used</source>
        <comment>grbl.profile.grbl_axis_used</comment>
        <translation>GRBL 的 %1 轴已被占用</translation>
    </message>
    <message>
        <source>the stage has no pump</source>
        <comment>grbl.profile.stage_no_pump</comment>
        <translation>载物台没有泵</translation>
    </message>
    <message>
        <source>GRBL axis %1 already drives another axis</source>
        <comment>grbl.profile.pump_axis_used</comment>
        <translation>GRBL 的 %1 轴已用于驱动另一个轴</translation>
    </message>
    <message>
        <source>must be above 0 and at most %2 (got %1)</source>
        <comment>grbl.profile.ul_per_mm_range</comment>
        <translation>必须大于 0 且不大于 %2（当前为 %1）</translation>
    </message>
    <message>
        <source>must exceed link_latency_s + refresh_s + 0.01 s (%2), or not even a creeping jog can keep it (got %1)</source>
        <comment>grbl.profile.stop_budget_too_small</comment>
        <translation>必须大于 link_latency_s + refresh_s + 0.01 s（%2），否则即使极慢的点动也无法满足（当前为 %1）</translation>
    </message>
    <message>
        <source>unlock</source>
        <comment>grbl.request.unlock</comment>
        <translation>解锁</translation>
    </message>
    <message>
        <source>dwell</source>
        <comment>grbl.request.dwell</comment>
        <translation>停留</translation>
    </message>
    <message>
        <source>trigger</source>
        <comment>grbl.request.trigger</comment>
        <translation>触发</translation>
    </message>
    <message>
        <source>status</source>
        <comment>grbl.request.status</comment>
        <translation>状态查询</translation>
    </message>
    <message>
        <source>a code this version of BenchPilot does not know</source>
        <translation>此版本 BenchPilot 不认识的代码</translation>
    </message>
    <message>
        <source>The jog runs at %1 instead of %2, so that it stops within %3 of a release, and of a lost link.</source>
        <translation>点动以 %1 而不是 %2 运行，以便在松开按键或连接中断后 %3 内停住。</translation>
    </message>
    <message>
        <source>The controller says: %1</source>
        <translation>控制器消息：%1</translation>
    </message>
    <message>
        <source>The controller sent: %1</source>
        <translation>控制器发送：%1</translation>
    </message>
    <message>
        <source>A line from the controller was not understood and was ignored (%1 so far): %2</source>
        <translation>控制器发来的一行无法理解，已忽略（迄今共 %1 行）：%2</translation>
    </message>
    <message>
        <source>The controller sent a line longer than %1; the rest of it was dropped (noise, or a wrong baud rate?).</source>
        <translation>控制器发来的一行超过 %1；超出部分已丢弃（有干扰，或波特率错误？）。</translation>
    </message>
    <message>
        <source>The controller reset by itself; its position is no longer trusted.</source>
        <translation>控制器自行复位；其位置已不可信。</translation>
    </message>
    <message>
        <source>The controller reset by itself: %1 lines were lost (the first &quot;%2&quot;); its position is no longer trusted.</source>
        <translation>控制器自行复位：丢失了 %1 行（第一行为“%2”）；其位置已不可信。</translation>
    </message>
    <message>
        <source>homing is disabled on the controller ($22=0): take the present position as home instead (Set home here)</source>
        <translation>控制器上已禁用回零（$22=0）：请改为将当前位置作为零位（“设此处为原点”）</translation>
    </message>
    <message>
        <source>GRBL drives its steppers open loop, with no encoder to read and no loop to tune</source>
        <translation>GRBL 以开环方式驱动步进电机，没有可读取的编码器，也没有可整定的回路</translation>
    </message>
    <message>
        <source>GRBL cannot notice that BenchPilot went away; what is queued ahead of a jog runs out within the machine profile&apos;s stop budget (250 ms unless it says otherwise)</source>
        <translation>GRBL 无法察觉 BenchPilot 已断开；点动之前排队的指令会在机器配置的停止时限内执行完（未另行指定时为 250 ms）</translation>
    </message>
    <message>
        <source>GRBL enforces only its machine travel ($130–$132)</source>
        <translation>GRBL 只限制其机床行程（$130–$132）</translation>
    </message>
    <message>
        <source>its X and Y are not GRBL&apos;s X and Y, and GRBL draws arcs only in its XY plane</source>
        <translation>其 X、Y 轴不是 GRBL 的 X、Y 轴，而 GRBL 只能在其 XY 平面内走圆弧</translation>
    </message>
    <message>
        <source>the machine profile names no pump axis</source>
        <translation>机器配置未指定泵轴</translation>
    </message>
    <message>
        <source>the machine profile names no trigger output</source>
        <translation>机器配置未指定触发输出</translation>
    </message>
    <message>
        <source>the controller has not restarted since home was set here: %1 keep their established positions</source>
        <comment>grbl.home_kept</comment>
        <translation>自在此设定原点以来控制器未曾重启：%1 保持确定的位置</translation>
    </message>
    <message>
        <source>the controller restarted as the port opened (its start-up message came): %1 have no established position until home is set again</source>
        <comment>grbl.home_lost_restart</comment>
        <translation>打开端口时控制器重启了（收到了其启动信息）：在重新设定原点之前，%1 没有确定的位置</translation>
    </message>
    <message>
        <source>the controller&apos;s work offset or machine position is not what it was when home was set here (it restarted, or another program moved it): %1 have no established position until home is set again</source>
        <comment>grbl.home_lost_changed</comment>
        <translation>控制器的工件偏移或机床坐标与在此设定原点时不同（它重启过，或被其他程序移动过）：在重新设定原点之前，%1 没有确定的位置</translation>
    </message>
    <message>
        <source>the home set here cannot be remembered in %1: the next connection will not keep it</source>
        <comment>grbl.home_not_saved</comment>
        <translation>无法在 %1 中记住在此设定的原点：下次连接时不会保留</translation>
    </message>
    <message>
        <source>%1 %2 is beyond the machine travel %3 … %4 (work coordinates, G54; the controller&apos;s $%5): refused before sending, since GRBL would stop with ALARM:2 and need a reset</source>
        <comment>grbl.beyond_travel</comment>
        <translation>%1 %2 超出机床行程 %3 … %4（工件坐标 G54；控制器的 $%5）：发送前已拒绝，否则 GRBL 会以 ALARM:2 停机并需要复位</translation>
    </message>
    <message>
        <source>work position (G54) %1, machine position %2</source>
        <comment>grbl.event.position</comment>
        <translation>工件坐标（G54）%1，机床坐标 %2</translation>
    </message>
</context>
<context>
    <name>ui::words::GrblWords</name>
    <message>
        <source>error %1: %2 (answering &quot;%3&quot;)</source>
        <comment>grbl.error.worded</comment>
        <translation>错误 %1：%2（对应“%3”）</translation>
    </message>
    <message>
        <source>error %1: %2</source>
        <comment>grbl.error.worded_no_line</comment>
        <translation>错误 %1：%2</translation>
    </message>
    <message>
        <source>alarm %1: %2</source>
        <comment>grbl.alarm.worded</comment>
        <translation>报警 %1：%2</translation>
    </message>
    <message>
        <source>a code this BenchPilot does not know (see the controller&apos;s documentation)</source>
        <comment>grbl.error.unknown_code</comment>
        <translation>本 BenchPilot 不认识的代码（请查阅控制器文档）</translation>
    </message>
    <message>
        <source>a code this BenchPilot does not know (see the controller&apos;s documentation)</source>
        <comment>grbl.alarm.unknown_code</comment>
        <translation>本 BenchPilot 不认识的代码（请查阅控制器文档）</translation>
    </message>
    <message>
        <source>a status report that cannot be read (%1): %2</source>
        <comment>grbl.status.malformed</comment>
        <translation>无法解读的状态报告（%1）：%2</translation>
    </message>
    <message>
        <source>$%1 (%2) is missing from the settings ($$)</source>
        <comment>grbl.settings.missing</comment>
        <translation>设置（$$）中缺少 $%1（%2 轴）</translation>
    </message>
    <message>
        <source>$%1 (%2) is %3: it must be above 0</source>
        <comment>grbl.settings.invalid</comment>
        <translation>$%1（%2 轴）为 %3：必须大于 0</translation>
    </message>
    <message>
        <source>$13=1: the controller reports in inches; BenchPilot converts them to mm</source>
        <comment>grbl.settings.report_inches</comment>
        <translation>$13=1：控制器以英寸报告；BenchPilot 将其换算为 mm</translation>
    </message>
    <message>
        <source>$20=1 with $22=0: soft limits are on but homing is off, so the limits have no reference</source>
        <comment>grbl.settings.soft_limits_without_homing</comment>
        <translation>$20=1 而 $22=0：软限位已开启但回零未开启，限位没有基准</translation>
    </message>
    <message>
        <source>even a creeping jog cannot stop within %1: the link takes %2 and jogs are refreshed every %3</source>
        <comment>grbl.jog.budget_too_small</comment>
        <translation>即使极慢的点动也无法在 %1 内停住：链路延迟 %2，点动每 %3 刷新一次</translation>
    </message>
    <message>
        <source>the %1 word is not a finite number</source>
        <comment>grbl.gcode.not_finite</comment>
        <translation>%1 字的数值不是有限数</translation>
    </message>
    <message>
        <source>the feed %1 must be above 0</source>
        <comment>grbl.gcode.bad_feed</comment>
        <translation>进给速度 %1 必须大于 0</translation>
    </message>
    <message>
        <source>the dwell %1 must be 0 or more</source>
        <comment>grbl.gcode.bad_dwell</comment>
        <translation>停留时间 %1 必须不小于 0</translation>
    </message>
    <message>
        <source>%1 is not an axis GRBL moves</source>
        <comment>grbl.gcode.bad_axis</comment>
        <translation>%1 不是 GRBL 控制的轴</translation>
    </message>
    <message>
        <source>a move needs at least one axis</source>
        <comment>grbl.gcode.no_axes</comment>
        <translation>一次移动至少需要一个轴</translation>
    </message>
    <message>
        <source>output port %1 is not one GRBL has</source>
        <comment>grbl.gcode.bad_port</comment>
        <translation>GRBL 没有输出口 %1</translation>
    </message>
    <message>
        <source>$%1 is not a setting number</source>
        <comment>grbl.gcode.bad_setting</comment>
        <translation>$%1 不是设置编号</translation>
    </message>
    <message>
        <source>the line is longer than GRBL accepts (%1): %2</source>
        <comment>grbl.gcode.too_long</comment>
        <translation>该行超过 GRBL 允许的长度（%1）：%2</translation>
    </message>
    <message>
        <source>unknown state</source>
        <comment>grbl.status.unknown_state</comment>
        <translation>未知状态</translation>
    </message>
    <message>
        <source>bad sub-state</source>
        <comment>grbl.status.bad_substate</comment>
        <translation>子状态无效</translation>
    </message>
    <message>
        <source>bad position</source>
        <comment>grbl.status.bad_position</comment>
        <translation>位置无效</translation>
    </message>
    <message>
        <source>bad work offset</source>
        <comment>grbl.status.bad_offset</comment>
        <translation>工件坐标偏置无效</translation>
    </message>
    <message>
        <source>bad buffer state</source>
        <comment>grbl.status.bad_buffer</comment>
        <translation>缓冲区状态无效</translation>
    </message>
    <message>
        <source>bad line number</source>
        <comment>grbl.status.bad_line_number</comment>
        <translation>行号无效</translation>
    </message>
    <message>
        <source>bad feed and speed</source>
        <comment>grbl.status.bad_feed</comment>
        <translation>进给与转速无效</translation>
    </message>
    <message>
        <source>bad pin state</source>
        <comment>grbl.status.bad_pins</comment>
        <translation>引脚状态无效</translation>
    </message>
    <message>
        <source>bad overrides</source>
        <comment>grbl.status.bad_overrides</comment>
        <translation>倍率无效</translation>
    </message>
    <message>
        <source>bad accessory state</source>
        <comment>grbl.status.bad_accessories</comment>
        <translation>附件状态无效</translation>
    </message>
    <message>
        <source>no position</source>
        <comment>grbl.status.no_position</comment>
        <translation>没有位置</translation>
    </message>
    <message>
        <source>%1 refused by the controller: error %2: %3 (answering &quot;%4&quot;)</source>
        <comment>grbl.error.refused</comment>
        <translation>%1 被控制器拒绝：错误 %2：%3（应答“%4”）</translation>
    </message>
    <message>
        <source>%1 refused by the controller: error %2: %3</source>
        <comment>grbl.error.refused_no_line</comment>
        <translation>%1 被控制器拒绝：错误 %2：%3</translation>
    </message>
</context>
<context>
    <name>ui::words::GridWords</name>
    <message>
        <source>%1 × %2 nodes: a map has at most %3 a side</source>
        <translation>%1 × %2 个节点：网格图每边最多 %3 个</translation>
    </message>
    <message>
        <source>a pitch of %1 is not a whole multiple of the plate&apos;s pitch %2: a node would find another node&apos;s dot</source>
        <translation>间距 %1 不是网格板间距 %2 的整数倍：节点会找到另一个节点的圆点</translation>
    </message>
    <message>
        <source>the grid reaches %2 on %1, beyond the travel&apos;s end at %3</source>
        <translation>网格在 %1 轴上到达 %2，超出行程终点 %3</translation>
    </message>
    <message>
        <source>no dot to start from under the camera: %1</source>
        <translation>相机下没有可作起点的圆点：%1</translation>
    </message>
    <message>
        <source>from the dot found at (%1, %2) the grid leaves the travel: %3</source>
        <translation>从 (%1, %2) 处找到的圆点出发，网格超出行程：%3</translation>
    </message>
    <message>
        <source>node %1 (column %2, row %3) has no reading: %4</source>
        <translation>节点 %1（第 %2 列，第 %3 行）没有读数：%4</translation>
    </message>
    <message>
        <source>%1 of %2 nodes have no reading: no map until they are read (run again into the same folder to try them again)</source>
        <translation>%2 个节点中有 %1 个没有读数：读完之前没有网格图（在同一文件夹中再次运行即可重试这些节点）</translation>
    </message>
    <message>
        <source>a grid map needs an instrument with X and Y axes</source>
        <translation>网格图需要带 X 和 Y 轴的仪器</translation>
    </message>
    <message>
        <source>this reading source reads one axis at a time; a grid map needs X and Y in one reading (the camera on a grid plate)</source>
        <translation>此读数来源一次只读一个轴；网格图需要一次读数同时给出 X 和 Y（相机对准网格板）</translation>
    </message>
    <message>
        <source>a line that is not part of a grid map&apos;s run log</source>
        <translation>不属于网格图运行日志的一行</translation>
    </message>
    <message>
        <source>%1 × %2 nodes: a map needs at least %3 a side</source>
        <translation>%1 × %2 个节点：网格图每边至少需要 %3 个</translation>
    </message>
    <message>
        <source>position %1 does not come after %2: a grid&apos;s positions must increase</source>
        <translation>位置 %1 不在 %2 之后：网格位置必须递增</translation>
    </message>
    <message>
        <source>%1 nodes, where the grid has %2</source>
        <translation>%1 个节点，而网格有 %2 个</translation>
    </message>
    <message>
        <source>the node at (%1, %2) is off the grid, whose node here is at (%3, %4)</source>
        <translation>位于 (%1, %2) 的节点不在网格上，网格在此处的节点位于 (%3, %4)</translation>
    </message>
    <message>
        <source>%1 coefficients: at most %2 (order 5)</source>
        <translation>%1 个系数：最多 %2 个（5 阶）</translation>
    </message>
    <message>
        <source>the curve reaches %1 at %2, beyond ±%3</source>
        <translation>曲线在 %2 处达到 %1，超出 ±%3</translation>
    </message>
    <message>
        <source>%1 nodes: a 2D table has %2 to %3 a side</source>
        <translation>%1 个节点：二维表每边应有 %2 到 %3 个节点</translation>
    </message>
    <message>
        <source>this instrument keeps no 2D compensation table</source>
        <translation>此仪器不保存二维补偿表</translation>
    </message>
    <message>
        <source>the device answered COMP2D_UPLOAD with something unreadable</source>
        <translation>设备对 COMP2D_UPLOAD 的应答无法解读</translation>
    </message>
    <message>
        <source>the device answered COMP2D_ENABLE with something unreadable</source>
        <translation>设备对 COMP2D_ENABLE 的应答无法解读</translation>
    </message>
    <message>
        <source>the nodes of %1 are not on one regular grid: no 2D table can be made of them</source>
        <translation>%1 的节点不在同一规则网格上：无法由其生成二维表</translation>
    </message>
    <message>
        <source>upload the 2D compensation table</source>
        <translation>上传二维补偿表</translation>
    </message>
    <message>
        <source>enable the 2D compensation table</source>
        <translation>启用二维补偿表</translation>
    </message>
    <message>
        <source>disable the 2D compensation table</source>
        <translation>禁用二维补偿表</translation>
    </message>
    <message>
        <source>read the 2D compensation table&apos;s state</source>
        <translation>读取二维补偿表状态</translation>
    </message>
</context>
<context>
    <name>ui::words::IdentityWords</name>
    <message>
        <source>BenchPilot analyzer manipulator (simulated)</source>
        <translation>BenchPilot 分析仪机械手（模拟）</translation>
    </message>
    <message>
        <source>BenchPilot microscope stage (simulated)</source>
        <translation>BenchPilot 显微镜载物台（模拟）</translation>
    </message>
</context>
<context>
    <name>ui::words::ImagingWords</name>
    <message>
        <source>cannot be read as a TIFF image (%1)</source>
        <comment>imaging.tiff.unreadable</comment>
        <translation>无法作为 TIFF 图像读取（%1）</translation>
    </message>
    <message>
        <source>the image is damaged or cut short (%1)</source>
        <comment>imaging.tiff.damaged</comment>
        <translation>图像已损坏或不完整（%1）</translation>
    </message>
    <message>
        <source>the image is %1 × %2 pixels: a tile must be from 1 to 65536 pixels each way</source>
        <comment>imaging.tiff.bad_size</comment>
        <translation>图像为 %1 × %2 像素：图块每个方向必须在 1 到 65536 像素之间</translation>
    </message>
    <message>
        <source>the image has %2 samples of %1 bits a pixel: tiles must be 8- or 16-bit grey, or 8-bit RGB</source>
        <comment>imaging.tiff.unsupported</comment>
        <translation>图像每像素有 %2 个 %1 位采样：图块必须是 8 位或 16 位灰度，或 8 位 RGB</translation>
    </message>
    <message>
        <source>there are no tiles to stitch</source>
        <comment>imaging.tiles.none</comment>
        <translation>没有可拼接的图块</translation>
    </message>
    <message>
        <source>this tile is %1 × %2 pixels but %3 is %4 × %5: every tile of a mosaic must be the same size</source>
        <comment>imaging.tiles.mixed_size</comment>
        <translation>此图块为 %1 × %2 像素，而 %3 为 %4 × %5：同一全景图的所有图块必须大小相同</translation>
    </message>
    <message>
        <source>this tile is %1 but %2 is %3: every tile of a mosaic must be of one kind (grey8, grey16 or rgb8)</source>
        <comment>imaging.tiles.mixed_kind</comment>
        <translation>此图块为 %1，而 %2 为 %3：同一全景图的所有图块必须是同一种类（grey8、grey16 或 rgb8）</translation>
    </message>
    <message>
        <source>a mosaic of %1 × %2 pixels cannot be written</source>
        <comment>imaging.mosaic.bad_size</comment>
        <translation>无法写出 %1 × %2 像素的全景图</translation>
    </message>
    <message>
        <source>the file cannot be created (%1)</source>
        <comment>imaging.mosaic.cannot_create</comment>
        <translation>无法创建该文件（%1）</translation>
    </message>
    <message>
        <source>writing the file failed (%1); nothing was left under its name</source>
        <comment>imaging.mosaic.write_failed</comment>
        <translation>写入文件失败（%1）；该文件名下未留下任何内容</translation>
    </message>
    <message>
        <source>tile %1 changed size while the mosaic was being written</source>
        <comment>imaging.mosaic.tile_changed</comment>
        <translation>写全景图期间图块 %1 的大小发生了变化</translation>
    </message>
    <message>
        <source>a tile line comes before &apos;dim = 2&apos;</source>
        <comment>imaging.tileconfig.no_dim</comment>
        <translation>图块行出现在“dim = 2”之前</translation>
    </message>
    <message>
        <source>the dimensions must be &apos;dim = 2&apos; (or 3)</source>
        <comment>imaging.tileconfig.bad_dim</comment>
        <translation>维数必须是“dim = 2”（或 3）</translation>
    </message>
    <message>
        <source>a tile line needs three fields separated by &apos;;&apos; (file; name; (x, y)), this one has %1</source>
        <comment>imaging.tileconfig.not_three_fields</comment>
        <translation>图块行需要三个以“;”分隔的字段（文件; 名称; (x, y)），此行有 %1 个</translation>
    </message>
    <message>
        <source>the position must be (x, y) in pixels, one number for each dimension</source>
        <comment>imaging.tileconfig.bad_position</comment>
        <translation>位置必须是以像素为单位的 (x, y)，每个维度一个数</translation>
    </message>
    <message>
        <source>the tile line names no file</source>
        <comment>imaging.tileconfig.no_file</comment>
        <translation>图块行未给出文件名</translation>
    </message>
    <message>
        <source>the file places no tiles</source>
        <comment>imaging.tileconfig.no_tiles</comment>
        <translation>文件中没有任何图块位置</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a file name in the folder (empty, or with a folder in it)</source>
        <comment>imaging.positions.bad_image_name</comment>
        <translation>“%1”不是文件夹中的文件名（为空，或含有文件夹路径）</translation>
    </message>
    <message>
        <source>%1 (or its tile number) is taken twice in the log</source>
        <comment>imaging.positions.duplicate</comment>
        <translation>%1（或其图块编号）在日志中出现了两次</translation>
    </message>
    <message>
        <source>%1 records no tile taken yet</source>
        <comment>imaging.positions.no_tiles</comment>
        <translation>%1 中尚无已拍摄的图块</translation>
    </message>
    <message>
        <source>%1 of the %2 tiles were taken: the live mosaic is placed only when every tile is there</source>
        <comment>imaging.live.incomplete</comment>
        <translation>%2 个图块中只采集了 %1 个：实时全景图要等所有图块齐全后才定位</translation>
    </message>
    <message>
        <source>the live stitch was stopped before it finished</source>
        <comment>imaging.live.cancelled</comment>
        <translation>实时拼接在完成前已停止</translation>
    </message>
    <message>
        <source>the image is %1 × %2 pixels: finding a line needs at least %3 pixels each way</source>
        <comment>imaging.line.image_too_small</comment>
        <translation>图像为 %1 × %2 像素：寻找刻线要求每个方向至少 %3 像素</translation>
    </message>
    <message>
        <source>the profile has %1 samples: finding a line needs at least %2</source>
        <comment>imaging.line.too_short</comment>
        <translation>轮廓只有 %1 个采样点：寻找刻线至少需要 %2 个</translation>
    </message>
    <message>
        <source>no graduation line found: the strongest mark stands out by %1 and a line needs %2 (blank glass, or out of focus)</source>
        <comment>imaging.line.not_found</comment>
        <translation>未找到刻线：最明显的标记对比度为 %1，而刻线需要 %2（空白玻璃，或未对焦）</translation>
    </message>
    <message>
        <source>two lines are equally near the image centre (at %1 px and %2 px from it): which one to read cannot be told</source>
        <comment>imaging.line.ambiguous</comment>
        <translation>两条刻线离图像中心一样近（距中心 %1 px 和 %2 px）：无法判断读哪一条</translation>
    </message>
    <message>
        <source>the image is %1 × %2 pixels: finding a dot needs at least %3 pixels each way</source>
        <comment>imaging.dot.image_too_small</comment>
        <translation>图像为 %1 × %2 像素：寻找圆点要求每个方向至少 %3 像素</translation>
    </message>
    <message>
        <source>no dot found: the strongest mark stands out by %1 and a dot needs %2 (blank glass, or out of focus)</source>
        <comment>imaging.dot.not_found</comment>
        <translation>未找到圆点：最明显的标记对比度为 %1，而圆点需要 %2（空白玻璃，或未对焦）</translation>
    </message>
    <message>
        <source>two dots are equally near the image centre (%1 px and %2 px from it): which one to read cannot be told</source>
        <comment>imaging.dot.ambiguous</comment>
        <translation>两个圆点离图像中心一样近（距中心 %1 px 和 %2 px）：无法判断读哪一个</translation>
    </message>
    <message>
        <source>the dot nearest the centre (%1 px, %2 px from it) is cut by the edge of the image: its centre cannot be measured</source>
        <comment>imaging.dot.at_edge</comment>
        <translation>离中心最近的圆点（距中心 %1 px，%2 px）被图像边缘截断：无法测量其中心</translation>
    </message>
    <message>
        <source>the mosaic has %2 samples of %1 bits a pixel: a mosaic to view must be 8- or 16-bit grey</source>
        <comment>imaging.pyramid.unsupported</comment>
        <translation>拼接图每像素有 %2 个 %1 位采样：可查看的拼接图必须是 8 位或 16 位灰度</translation>
    </message>
    <message>
        <source>the images are mirrored against the plan&apos;s camera: set the camera&apos;s image y to %1 (the plan says %2)</source>
        <comment>imaging.camera_check.mirrored</comment>
        <translation>图像相对计划中的相机是镜像的：请把相机的 image y 设为 %1（计划中为 %2）</translation>
    </message>
    <message>
        <source>the neighbours&apos; shifts show the camera turned %1 against the stage: set the camera&apos;s rotation to %1 (the plan says %2)</source>
        <comment>imaging.camera_check.rotated</comment>
        <translation>相邻图块的位移表明相机相对载物台旋转了 %1：请把相机的旋转设为 %1（计划中为 %2）</translation>
    </message>
    <message>
        <source>the neighbours&apos; shifts show a pixel of %1 at the sample: set the camera&apos;s pixel size to %1 (the plan says %2), or calibrate the camera</source>
        <comment>imaging.camera_check.pixel</comment>
        <translation>相邻图块的位移表明样品处的像素为 %1：请把相机的像素尺寸设为 %1（计划中为 %2），或标定相机</translation>
    </message>
    <message>
        <source>level %1 of the mosaic&apos;s pyramid cannot be read (%2)</source>
        <comment>imaging.pyramid.bad_level</comment>
        <translation>无法读取拼接图金字塔的第 %1 层（%2）</translation>
    </message>
    <message>
        <source>the blank image is empty</source>
        <comment>imaging.flat.empty</comment>
        <translation>空白图像为空</translation>
    </message>
    <message>
        <source>the blank image averages %1 grey levels, no more than the camera&apos;s offset of %2: take it with the light on</source>
        <comment>imaging.flat.dark</comment>
        <translation>空白图像平均只有 %1 灰度级，不高于相机偏置 %2：请在照明打开时拍摄</translation>
    </message>
    <message>
        <source>%1 % of the blank image is saturated: take it with less light or a shorter exposure</source>
        <comment>imaging.flat.clipped</comment>
        <translation>空白图像有 %1 % 饱和：请减弱照明或缩短曝光</translation>
    </message>
    <message>
        <source>%1 % of the blank image is darker than a tenth of its mean: a blank is evenly lit bare glass, not a specimen</source>
        <comment>imaging.flat.holes</comment>
        <translation>空白图像有 %1 % 暗于其均值的十分之一：空白图像应是照明均匀的空玻璃，而不是样品</translation>
    </message>
    <message>
        <source>this tile is %1 × %2 pixels but the blank image %3 is %4 × %5: the blank must come from the same camera and binning</source>
        <comment>imaging.flat.size</comment>
        <translation>该图块为 %1 × %2 像素，而空白图像 %3 为 %4 × %5：空白图像必须来自同一相机和同一像素合并设置</translation>
    </message>
</context>
<context>
    <name>ui::words::PatternWords</name>
    <message>
        <source>must be a number</source>
        <comment>pattern.not_a_number</comment>
        <translation>必须是数字</translation>
    </message>
    <message>
        <source>must be two numbers [x, y]</source>
        <comment>pattern.not_a_point</comment>
        <translation>必须是两个数 [x, y]</translation>
    </message>
    <message>
        <source>must be above %1 (got %2)</source>
        <comment>pattern.not_above</comment>
        <translation>必须大于 %1（当前为 %2）</translation>
    </message>
    <message>
        <source>must be from %1 to %2 (got %3)</source>
        <comment>pattern.out_of_range</comment>
        <translation>必须在 %1 到 %2 之间（当前为 %3）</translation>
    </message>
    <message>
        <source>must differ from start_mm: the line has no length</source>
        <comment>pattern.line_has_no_length</comment>
        <translation>必须与 start_mm 不同：直线长度为零</translation>
    </message>
    <message>
        <source>gives %1 chords, more than %2: loosen it or shorten the wave</source>
        <comment>pattern.too_many_chords</comment>
        <translation>将产生 %1 段弦，超过 %2：请放宽容差或缩短波形</translation>
    </message>
    <message>
        <source>must be a whole or half number of turns (got %1)</source>
        <comment>pattern.not_half_turns</comment>
        <translation>必须是整圈或半圈（当前为 %1）</translation>
    </message>
    <message>
        <source>gives %1 passes: too many (at most %2), widen the spacing</source>
        <comment>pattern.too_many_passes</comment>
        <translation>将产生 %1 道扫描，过多（最多 %2）：请加大间距</translation>
    </message>
    <message>
        <source>segment %1 (%2) reaches %3 = %4, beyond the upper soft limit %5</source>
        <comment>pattern.segment_above_limit</comment>
        <translation>第 %1 段（%2）到达 %3 = %4，超出正向软限位 %5</translation>
    </message>
    <message>
        <source>segment %1 (%2) reaches %3 = %4, beyond the lower soft limit %5</source>
        <comment>pattern.segment_below_limit</comment>
        <translation>第 %1 段（%2）到达 %3 = %4，超出负向软限位 %5</translation>
    </message>
    <message>
        <source>The instrument was replaced by another connection.</source>
        <comment>pattern.run.replaced</comment>
        <translation>仪器已被另一个连接替换。</translation>
    </message>
    <message>
        <source>The instrument ran out of queued segments and waited for more: the link is slower than the pattern.</source>
        <comment>pattern.run.underrun</comment>
        <translation>仪器的队列段已用完，只能等待后续段：通信链路跟不上图形的速度。</translation>
    </message>
    <message>
        <source>Pattern done in %1: contour error max %2, RMS %3 (%4 samples at %5).</source>
        <comment>pattern.run.done</comment>
        <translation>图形运行完成，用时 %1：轮廓误差最大 %2，均方根 %3（%4 个采样点，采样率 %5）。</translation>
    </message>
    <message>
        <source>The instrument paused the pattern: %1. Press Resume to go on.</source>
        <comment>pattern.run.held</comment>
        <translation>仪器暂停了图形：%1。按“继续”接着运行。</translation>
    </message>
    <message>
        <source>Pattern aborted at segment %1 of %2.</source>
        <comment>pattern.run.aborted</comment>
        <translation>图形在第 %1 段（共 %2 段）处中止。</translation>
    </message>
    <message>
        <source>The instrument stopped the pattern at segment %1 (%2). Press Resume to continue from there.</source>
        <comment>pattern.run.stopped_by_instrument</comment>
        <translation>仪器在第 %1 段停止了图形（%2）。按“继续”从该处接着运行。</translation>
    </message>
    <message>
        <source>The instrument is not connected or cannot run paths.</source>
        <comment>pattern.run.no_path_queue</comment>
        <translation>仪器未连接，或不能运行路径。</translation>
    </message>
    <message>
        <source>The pattern has no segments.</source>
        <comment>pattern.run.no_segments</comment>
        <translation>图形中没有任何段。</translation>
    </message>
    <message>
        <source>The E-stop is active: reset it first.</source>
        <comment>pattern.run.estop_active</comment>
        <translation>急停已触发：请先复位急停。</translation>
    </message>
    <message>
        <source>The instrument is still moving: wait until it is at rest.</source>
        <comment>pattern.run.still_moving</comment>
        <translation>仪器仍在运动：请等待其停稳。</translation>
    </message>
    <message>
        <source>Axis %1 is not homed: home it first.</source>
        <comment>pattern.run.not_homed</comment>
        <translation>%1 轴尚未回零：请先回零。</translation>
    </message>
    <message>
        <source>This instrument has no Z axis to work at a height.</source>
        <comment>pattern.run.no_z</comment>
        <translation>该仪器没有 Z 轴，不能在指定高度上工作。</translation>
    </message>
    <message>
        <source>Z %1 is outside its soft limits %2 … %3.</source>
        <comment>pattern.run.z_outside_limits</comment>
        <translation>Z = %1 超出其软限位 %2 … %3。</translation>
    </message>
    <message>
        <source>Segment %1: feed %2 is above the instrument&apos;s %3.</source>
        <comment>pattern.run.feed_too_high</comment>
        <translation>第 %1 段：进给速度 %2 超过仪器的最大值 %3。</translation>
    </message>
    <message>
        <source>Cannot move to the pattern&apos;s start: %1</source>
        <comment>pattern.run.approach_refused</comment>
        <translation>无法移动到图形起点：%1</translation>
    </message>
    <message>
        <source>The move to the pattern&apos;s start was stopped before it arrived. Press Resume to try again.</source>
        <comment>pattern.run.approach_stopped</comment>
        <translation>移动到图形起点的过程在到达前被停止。按“继续”重试。</translation>
    </message>
    <message>
        <source>The instrument refused the pattern: %1</source>
        <comment>pattern.run.refused</comment>
        <translation>仪器拒绝了该图形：%1</translation>
    </message>
    <message>
        <source>The link to the instrument was lost at segment %1 of %2. The instrument holds the path by itself within a second. Reconnect, then press Resume to continue from segment %1.</source>
        <comment>pattern.run.link_lost</comment>
        <translation>在第 %1 段（共 %2 段）处与仪器的连接中断。仪器会在一秒内自行停住路径。请重新连接，然后按“继续”从第 %1 段接着运行。</translation>
    </message>
    <message>
        <source>Reconnect the instrument first.</source>
        <comment>pattern.run.reconnect_first</comment>
        <translation>请先重新连接仪器。</translation>
    </message>
    <message>
        <source>Continuing from segment %1.</source>
        <comment>pattern.run.continuing</comment>
        <translation>从第 %1 段继续。</translation>
    </message>
    <message>
        <source>LINE</source>
        <comment>segment.line</comment>
        <translation>直线</translation>
    </message>
    <message>
        <source>ARC CW</source>
        <comment>segment.arc_cw</comment>
        <translation>顺时针圆弧</translation>
    </message>
    <message>
        <source>ARC CCW</source>
        <comment>segment.arc_ccw</comment>
        <translation>逆时针圆弧</translation>
    </message>
    <message>
        <source>ready</source>
        <comment>pattern.state.idle</comment>
        <translation>就绪</translation>
    </message>
    <message>
        <source>moving to the start</source>
        <comment>pattern.state.approaching</comment>
        <translation>正在移向起点</translation>
    </message>
    <message>
        <source>running</source>
        <comment>pattern.state.running</comment>
        <translation>运行中</translation>
    </message>
    <message>
        <source>paused</source>
        <comment>pattern.state.paused</comment>
        <translation>已暂停</translation>
    </message>
    <message>
        <source>done</source>
        <comment>pattern.state.done</comment>
        <translation>已完成</translation>
    </message>
    <message>
        <source>aborted</source>
        <comment>pattern.state.aborted</comment>
        <translation>已中止</translation>
    </message>
    <message>
        <source>interrupted</source>
        <comment>pattern.state.interrupted</comment>
        <translation>已中断</translation>
    </message>
    <message>
        <source>refused</source>
        <comment>pattern.state.failed</comment>
        <translation>被拒绝</translation>
    </message>
</context>
<context>
    <name>ui::words::PlateWords</name>
    <message>
        <source>must not be empty</source>
        <comment>plate.empty</comment>
        <translation>不能为空</translation>
    </message>
    <message>
        <source>must be more than 0 (got %1)</source>
        <comment>plate.not_positive</comment>
        <translation>必须大于 0（当前为 %1）</translation>
    </message>
    <message>
        <source>must be 0 or more (got %1)</source>
        <comment>plate.negative</comment>
        <translation>必须不小于 0（当前为 %1）</translation>
    </message>
    <message>
        <source>must be from %1 to %2 (got %3)</source>
        <comment>plate.out_of_range</comment>
        <translation>必须在 %1 到 %2 之间（当前为 %3）</translation>
    </message>
    <message>
        <source>must be more than 0 and at most %1 (got %2)</source>
        <comment>plate.size_out_of_range</comment>
        <translation>必须大于 0 且不大于 %1（当前为 %2）</translation>
    </message>
    <message>
        <source>more problems not shown</source>
        <comment>plate.more_not_shown</comment>
        <translation>还有更多问题未列出</translation>
    </message>
    <message>
        <source>unknown well %1 on a %2-well plate</source>
        <comment>plate.unknown_well</comment>
        <translation>%2 孔板上没有孔 %1</translation>
    </message>
    <message>
        <source>must be within the Z travel (at most %1, got %2)</source>
        <comment>plate.deck.table_beyond_travel</comment>
        <translation>必须在 Z 轴行程之内（不大于 %1，当前为 %2）</translation>
    </message>
    <message>
        <source>must be more than 0 and at most max_speed %1 (got %2)</source>
        <comment>plate.deck.default_speed_invalid</comment>
        <translation>必须大于 0 且不大于 max_speed %1（当前为 %2）</translation>
    </message>
    <message>
        <source>slot &quot;%1&quot; is defined twice</source>
        <comment>plate.deck.slot_twice</comment>
        <translation>板位“%1”被定义了两次</translation>
    </message>
    <message>
        <source>a plate in slot &quot;%1&quot; would cover X %2–%3, Y %4–%5, outside the travel 0–%6 × 0–%7</source>
        <comment>plate.deck.slot_outside_travel</comment>
        <translation>板位“%1”上的孔板将覆盖 X %2–%3、Y %4–%5，超出行程 0–%6 × 0–%7</translation>
    </message>
    <message>
        <source>slot &quot;%1&quot; overlaps slot &quot;%2&quot;</source>
        <comment>plate.deck.slots_overlap</comment>
        <translation>板位“%1”与板位“%2”重叠</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is already the id of a slot or station</source>
        <comment>plate.deck.id_taken</comment>
        <translation>“%1”已被某个板位或工位使用</translation>
    </message>
    <message>
        <source>station &quot;%1&quot; at (%2, %3) is outside the travel</source>
        <comment>plate.deck.station_outside_travel</comment>
        <translation>工位“%1”位于（%2, %3），超出行程</translation>
    </message>
    <message>
        <source>station &quot;%1&quot; needs 0 ≤ safe_z_mm &lt; depth_z_mm ≤ %2</source>
        <comment>plate.deck.station_heights</comment>
        <translation>工位“%1”须满足 0 ≤ safe_z_mm &lt; depth_z_mm ≤ %2</translation>
    </message>
    <message>
        <source>a deck needs at least one slot</source>
        <comment>plate.deck.no_slots</comment>
        <translation>台面至少需要一个板位</translation>
    </message>
    <message>
        <source>the grid must have 1–%1 rows and 1–%2 columns (got %3 × %4)</source>
        <comment>plate.labware.grid_size</comment>
        <translation>网格须有 1–%1 行、1–%2 列（当前为 %3 × %4）</translation>
    </message>
    <message>
        <source>a plate needs at least one well</source>
        <comment>plate.labware.no_wells</comment>
        <translation>孔板至少需要一个孔</translation>
    </message>
    <message>
        <source>well %1 is outside the %2 × %3 grid</source>
        <comment>plate.labware.well_outside_grid</comment>
        <translation>孔 %1 超出 %2 × %3 网格</translation>
    </message>
    <message>
        <source>well %1 is defined twice</source>
        <comment>plate.labware.well_twice</comment>
        <translation>孔 %1 被定义了两次</translation>
    </message>
    <message>
        <source>well %1 needs a size above 0</source>
        <comment>plate.labware.well_no_size</comment>
        <translation>孔 %1 的尺寸必须大于 0</translation>
    </message>
    <message>
        <source>well %1: its bottom (%2) plus its depth (%3) must be above 0 and at most the plate&apos;s height %4</source>
        <comment>plate.labware.well_depth</comment>
        <translation>孔 %1：孔底高度（%2）加孔深（%3）必须大于 0 且不超过板高 %4</translation>
    </message>
    <message>
        <source>well %1 needs a volume above 0 µL</source>
        <comment>plate.labware.well_no_volume</comment>
        <translation>孔 %1 的容积必须大于 0 µL</translation>
    </message>
    <message>
        <source>well %1 at (%2, %3) does not fit on the %4 × %5 footprint</source>
        <comment>plate.labware.well_off_footprint</comment>
        <translation>孔 %1 位于（%2, %3），超出 %4 × %5 的板面</translation>
    </message>
    <message>
        <source>names no wells</source>
        <comment>plate.wells.none</comment>
        <translation>没有指定任何孔</translation>
    </message>
    <message>
        <source>%1 needs a row letter, like &quot;row B&quot;</source>
        <comment>plate.wells.row_needs_letter</comment>
        <translation>%1 需要行字母，例如“row B”</translation>
    </message>
    <message>
        <source>unknown row %1 on a %2-well plate (rows A–%3)</source>
        <comment>plate.wells.unknown_row</comment>
        <translation>%2 孔板上没有行 %1（行为 A–%3）</translation>
    </message>
    <message>
        <source>%1 needs a column number, like &quot;column 3&quot;</source>
        <comment>plate.wells.column_needs_number</comment>
        <translation>%1 需要列号，例如“column 3”</translation>
    </message>
    <message>
        <source>unknown column %1 on a %2-well plate (columns 1–%3)</source>
        <comment>plate.wells.unknown_column</comment>
        <translation>%2 孔板上没有列 %1（列为 1–%3）</translation>
    </message>
    <message>
        <source>%1 is not a range of two wells, like &quot;A1:H1&quot;</source>
        <comment>plate.wells.bad_range</comment>
        <translation>%1 不是由两个孔构成的范围，例如“A1:H1”</translation>
    </message>
    <message>
        <source>%1 is not a well (&quot;A1&quot;), a range (&quot;A1:H1&quot;), &quot;row B&quot;, &quot;column 3&quot; or &quot;all&quot;</source>
        <comment>plate.wells.not_a_well_set</comment>
        <translation>%1 不是孔（“A1”）、范围（“A1:H1”）、“row B”、“column 3”或“all”</translation>
    </message>
    <message>
        <source>well %1 is named twice; dose a well twice with two steps</source>
        <comment>plate.wells.named_twice</comment>
        <translation>孔 %1 被指定了两次；同一孔加样两次请用两个步骤</translation>
    </message>
    <message>
        <source>teach at least two wells (three to see a residual)</source>
        <comment>plate.calibration.too_few_wells</comment>
        <translation>请至少示教两个孔（三个孔才能看到残差）</translation>
    </message>
    <message>
        <source>well %1 has no position</source>
        <comment>plate.calibration.no_position</comment>
        <translation>孔 %1 没有位置</translation>
    </message>
    <message>
        <source>the taught wells are less than 1 mm apart: teach wells at the plate&apos;s corners</source>
        <comment>plate.calibration.too_close</comment>
        <translation>示教的孔相距不到 1 mm：请示教孔板四角的孔</translation>
    </message>
    <message>
        <source>a scale per axis needs three taught wells</source>
        <comment>plate.calibration.scaled_needs_three</comment>
        <translation>按轴分别求比例需要示教三个孔</translation>
    </message>
    <message>
        <source>the taught wells lie on one line: a scale per axis needs a row and a column</source>
        <comment>plate.calibration.on_one_line</comment>
        <translation>示教的孔在一条直线上：按轴分别求比例需要一行和一列</translation>
    </message>
    <message>
        <source>the taught wells are up to %1 off the plate&apos;s shape (%2 mm; more than %3): one was taught off centre or on the wrong well; teach them again</source>
        <comment>plate.calibration.large_residual</comment>
        <translation>示教的孔与孔板形状最多相差 %1（%2 mm；超过 %3）：有孔示教偏离中心或示教错了孔；请重新示教</translation>
    </message>
    <message>
        <source>the fitted scale is %1: the taught wells are not as far apart as the labware says (wrong labware, or a well taught on its neighbour)</source>
        <comment>plate.calibration.scale_off</comment>
        <translation>拟合比例为 %1：示教孔之间的距离与耗材定义不符（耗材选错，或示教到了相邻的孔）</translation>
    </message>
    <message>
        <source>the plate sits turned by %1: is it seated flat in the slot?</source>
        <comment>plate.calibration.turned</comment>
        <translation>孔板转了 %1：是否平放在板位中？</translation>
    </message>
    <message>
        <source>give either &quot;grid&quot; or &quot;wells&quot;, not both</source>
        <comment>plate.file.grid_and_wells</comment>
        <translation>请给出“grid”或“wells”之一，不能同时给出</translation>
    </message>
    <message>
        <source>is missing: give the wells as a &quot;grid&quot; (A1 and pitch) or a list of &quot;wells&quot;</source>
        <comment>plate.file.no_grid</comment>
        <translation>缺失：请以“grid”（A1 与孔距）或“wells”列表给出孔</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a well name like &quot;A1&quot;</source>
        <comment>plate.file.not_a_well_name</comment>
        <translation>“%1”不是孔名，孔名形如“A1”</translation>
    </message>
    <message>
        <source>more than %1 wells</source>
        <comment>plate.file.too_many_wells</comment>
        <translation>孔数超过 %1</translation>
    </message>
    <message>
        <source>is %1; only Opentrons labware schema 2 is read</source>
        <comment>plate.file.opentrons_schema</comment>
        <translation>为 %1；只能读取 Opentrons 耗材定义第 2 版</translation>
    </message>
    <message>
        <source>this is a tip rack, not a plate: the analyzer has a fixed tip</source>
        <comment>plate.file.tip_rack</comment>
        <translation>这是吸头盒，不是孔板：分析仪使用固定加样针</translation>
    </message>
    <message>
        <source>must be an array of well names</source>
        <comment>plate.file.ordering_not_names</comment>
        <translation>必须是孔名数组</translation>
    </message>
    <message>
        <source>slot &quot;%1&quot; is calibrated twice</source>
        <comment>plate.file.slot_calibrated_twice</comment>
        <translation>板位“%1”被校准了两次</translation>
    </message>
    <message>
        <source>cannot fit the taught points: %1</source>
        <comment>plate.file.cannot_fit</comment>
        <translation>无法拟合示教点：%1</translation>
    </message>
</context>
<context>
    <name>ui::words::ProfileWords</name>
    <message>
        <source>%1 = %2 must be finite</source>
        <comment>profile.not_finite</comment>
        <translation>%1 = %2 必须是有限数</translation>
    </message>
    <message>
        <source>axis %1: %2 = %3 must be finite</source>
        <comment>profile.axis_not_finite</comment>
        <translation>第 %1 轴：%2 = %3 必须是有限数</translation>
    </message>
    <message>
        <source>%1 = %2 must be finite and above 0 for %3</source>
        <comment>profile.not_positive</comment>
        <translation>对 %3，%1 = %2 必须为大于 0 的有限数</translation>
    </message>
    <message>
        <source>%1 = %2 must be finite and above 0</source>
        <comment>profile.not_positive_plain</comment>
        <translation>%1 = %2 必须为大于 0 的有限数</translation>
    </message>
    <message>
        <source>axis %1: %2 = %3 must be finite and above 0</source>
        <comment>profile.axis_not_positive</comment>
        <translation>第 %1 轴：%2 = %3 必须为大于 0 的有限数</translation>
    </message>
    <message>
        <source>%1 = %2 must be finite and not negative for %3</source>
        <comment>profile.negative</comment>
        <translation>对 %3，%1 = %2 必须为非负的有限数</translation>
    </message>
    <message>
        <source>%1 = %2 must be from 0 to vMaxMmS for %3</source>
        <comment>profile.start_speed_above_max</comment>
        <translation>对 %3，%1 = %2 必须在 0 到 vMaxMmS 之间</translation>
    </message>
    <message>
        <source>%1 = %2 must be above 0 when plateauMm is above 0 for %3</source>
        <comment>profile.start_speed_for_plateau</comment>
        <translation>对 %3，当 plateauMm 大于 0 时 %1 = %2 必须大于 0</translation>
    </message>
    <message>
        <source>unknown profile kind</source>
        <comment>profile.unknown_kind</comment>
        <translation>未知的速度曲线类型</translation>
    </message>
    <message>
        <source>%1 axes: a move has 1 to %2</source>
        <comment>profile.axis_count</comment>
        <translation>%1 个轴：一次移动只能有 1 到 %2 个轴</translation>
    </message>
    <message>
        <source>path limits are not finite; check the per-axis limits</source>
        <comment>profile.path_limits_not_finite</comment>
        <translation>路径限值不是有限数；请检查各轴限值</translation>
    </message>
    <message>
        <source>path speed is not finite; check the per-axis vMaxMmS</source>
        <comment>profile.path_speed_not_finite</comment>
        <translation>路径速度不是有限数；请检查各轴的 vMaxMmS</translation>
    </message>
    <message>
        <source>joint %1 block %2: t0 = 0 ms must be above 0</source>
        <comment>profile.block_zero_duration</comment>
        <translation>关节 %1 块 %2：t0 = 0 ms，必须大于 0</translation>
    </message>
    <message>
        <source>joint %1 block %2: |V2| = %3 microsteps/s exceeds vMax = %4</source>
        <comment>profile.block_too_fast</comment>
        <translation>关节 %1 块 %2：|V2| = %3 微步/s，超过 vMax = %4</translation>
    </message>
    <message>
        <source>joint %1 block %2: S = %3 microsteps is not reachable from V1 = %4 to V2 = %5 microsteps/s in t0 = %6 (reachable %7 … %8)</source>
        <comment>profile.block_unreachable</comment>
        <translation>关节 %1 块 %2：在 t0 = %6 内从 V1 = %4 到 V2 = %5 微步/s 无法走完 S = %3 微步（可达 %7 … %8）</translation>
    </message>
</context>
<context>
    <name>ui::words::RecipeWords</name>
    <message>
        <source>a recipe has at most %1 steps (got %2)</source>
        <comment>recipe.too_many_steps</comment>
        <translation>一个方案最多 %1 个步骤（当前 %2 个）</translation>
    </message>
    <message>
        <source>plate &quot;%1&quot; is named twice</source>
        <comment>recipe.plate_named_twice</comment>
        <translation>孔板名“%1”重复</translation>
    </message>
    <message>
        <source>unknown slot &quot;%1&quot;: the deck has slots %2</source>
        <comment>recipe.unknown_slot</comment>
        <translation>未知板位“%1”：台面上的板位有 %2</translation>
    </message>
    <message>
        <source>slot &quot;%1&quot; already holds another plate of this recipe</source>
        <comment>recipe.slot_taken</comment>
        <translation>板位“%1”上已放了本方案的另一块孔板</translation>
    </message>
    <message>
        <source>unknown labware &quot;%1&quot; (built in: %2; or a labware file)</source>
        <comment>recipe.unknown_labware</comment>
        <translation>未知耗材“%1”（内置：%2；或使用耗材文件）</translation>
    </message>
    <message>
        <source>must be below the safe height (more than %1) and at most %2 (got %3)</source>
        <comment>recipe.depth_not_below_safe</comment>
        <translation>必须低于安全高度（大于 %1）且不大于 %2（当前为 %3）</translation>
    </message>
    <message>
        <source>a recipe needs at least one step</source>
        <comment>recipe.no_steps</comment>
        <translation>方案至少需要一个步骤</translation>
    </message>
    <message>
        <source>%1 is not above the plate: its top is at Z %2; the safe height must be smaller</source>
        <comment>recipe.safe_not_above_plate</comment>
        <translation>%1 不在孔板上方：板顶在 Z %2；安全高度必须更小</translation>
    </message>
    <message>
        <source>%1 is below the bottom of the wells (Z %2): the tip would hit it</source>
        <comment>recipe.depth_below_bottom</comment>
        <translation>%1 低于孔底（Z %2）：加样针会碰到孔底</translation>
    </message>
    <message>
        <source>missing plate: the recipe has no plates</source>
        <comment>recipe.no_plates</comment>
        <translation>缺少孔板：本方案没有孔板</translation>
    </message>
    <message>
        <source>missing plate: the recipe has %1 plates (%2); say which</source>
        <comment>recipe.plate_ambiguous</comment>
        <translation>缺少孔板：本方案有 %1 块孔板（%2）；请指明是哪一块</translation>
    </message>
    <message>
        <source>unknown plate &quot;%1&quot;; the recipe&apos;s plates are %2</source>
        <comment>recipe.unknown_plate</comment>
        <translation>未知孔板“%1”；本方案的孔板有 %2</translation>
    </message>
    <message>
        <source>unknown plate &quot;%1&quot;: the recipe has no plates</source>
        <comment>recipe.unknown_plate_none</comment>
        <translation>未知孔板“%1”：本方案没有孔板</translation>
    </message>
    <message>
        <source>well %1 of plate &quot;%2&quot; is at (%3, %4), outside the analyzer&apos;s travel (0–%5 × 0–%6): check the slot&apos;s calibration</source>
        <comment>recipe.well_outside_travel</comment>
        <translation>孔板“%2”的孔 %1 位于（%3, %4），超出分析仪行程（0–%5 × 0–%6）：请检查板位校准</translation>
    </message>
    <message>
        <source>unknown station &quot;%1&quot; (the deck has %2)</source>
        <comment>recipe.unknown_station</comment>
        <translation>未知工位“%1”（台面上的工位有 %2）</translation>
    </message>
    <message>
        <source>unknown station &quot;%1&quot;: the deck has none</source>
        <comment>recipe.unknown_station_none</comment>
        <translation>未知工位“%1”：台面上没有工位</translation>
    </message>
    <message>
        <source>the recipe visits more than %1 wells; split it into several recipes</source>
        <comment>recipe.too_many_ops</comment>
        <translation>该方案访问的孔超过 %1 个；请拆分成几个方案</translation>
    </message>
    <message>
        <source>well %1 of plate &quot;%2&quot; receives %3 in all; it holds %4</source>
        <comment>recipe.well_overfilled</comment>
        <translation>孔板“%2”的孔 %1 总共加入 %3；其容积为 %4</translation>
    </message>
    <message>
        <source>volume over capacity: %1 is more than the syringe holds (%2)</source>
        <comment>recipe.volume_over_capacity</comment>
        <translation>超出容量：%1 大于注射器容积（%2）</translation>
    </message>
    <message>
        <source>volume over capacity: the syringe would hold %1, more than its %2</source>
        <comment>recipe.syringe_overfull</comment>
        <translation>超出容量：注射器中将有 %1，超过其容积 %2</translation>
    </message>
    <message>
        <source>volume over capacity: the syringe would hold %1, more than its %2 (it holds %3 at this point)</source>
        <comment>recipe.syringe_overfull_holding</comment>
        <translation>超出容量：注射器中将有 %1，超过其容积 %2（此时已有 %3）</translation>
    </message>
    <message>
        <source>the plunger would pass its empty end (%1)</source>
        <comment>recipe.plunger_past_empty</comment>
        <translation>柱塞将越过排空端（%1）</translation>
    </message>
    <message>
        <source>give either wells or a station, not both</source>
        <comment>recipe.wells_and_station</comment>
        <translation>请给出孔或工位之一，不能同时给出</translation>
    </message>
    <message>
        <source>is missing: say which wells to aspirate from (or a station)</source>
        <comment>recipe.wells_missing_aspirate</comment>
        <translation>缺失：请指明从哪些孔吸液（或从哪个工位）</translation>
    </message>
    <message>
        <source>is missing: say which wells to dispense into (or a station)</source>
        <comment>recipe.wells_missing_dispense</comment>
        <translation>缺失：请指明向哪些孔排液（或向哪个工位）</translation>
    </message>
    <message>
        <source>%1 is more than a %2 well of plate &quot;%3&quot;</source>
        <comment>recipe.aspirate_over_well</comment>
        <translation>%1 超过孔板“%3”中 %2 的孔</translation>
    </message>
    <message>
        <source>%1 does not fit a %2 well of plate &quot;%3&quot;</source>
        <comment>recipe.dispense_over_well</comment>
        <translation>%1 装不进孔板“%3”中 %2 的孔</translation>
    </message>
    <message>
        <source>only a dispense takes a source</source>
        <comment>recipe.source_only_dispense</comment>
        <translation>只有排液步骤才能指定来源</translation>
    </message>
    <message>
        <source>%1 is past the wall of a well %2 wide</source>
        <comment>recipe.offset_past_wall</comment>
        <translation>%1 超出了宽 %2 的孔壁</translation>
    </message>
    <message>
        <source>dispensing %1 needs that much liquid in the syringe; it holds %2 here: aspirate first, or give the step a &quot;source&quot;</source>
        <comment>recipe.dispense_without_liquid</comment>
        <translation>排液 %1 需要注射器中有这么多液体；此处只有 %2：请先吸液，或为该步骤指定“source”</translation>
    </message>
    <message>
        <source>mixing %1 in a %2 well</source>
        <comment>recipe.mix_over_well</comment>
        <translation>在 %2 的孔中混匀 %1</translation>
    </message>
    <message>
        <source>is missing: say which station washes the tip</source>
        <comment>recipe.wash_station_missing</comment>
        <translation>缺失：请指明在哪个工位清洗加样针</translation>
    </message>
    <message>
        <source>give either a well or a station, not both</source>
        <comment>recipe.source_well_and_station</comment>
        <translation>请给出孔或工位之一，不能同时给出</translation>
    </message>
    <message>
        <source>the source is outside the analyzer&apos;s travel</source>
        <comment>recipe.source_outside_travel</comment>
        <translation>来源超出分析仪行程</translation>
    </message>
    <message>
        <source>volume over capacity: %1 per well, but the syringe has room for %2 here (%3 in all)</source>
        <comment>recipe.transfer_no_room</comment>
        <translation>超出容量：每孔 %1，但此处注射器只剩 %2 的空间（总容积 %3）</translation>
    </message>
    <message>
        <source>a round draws %1 from a %2 well</source>
        <comment>recipe.round_over_source</comment>
        <translation>一轮从 %2 的孔中吸取 %1</translation>
    </message>
    <message>
        <source>must be a string like &quot;A1&quot; or &quot;A1:H1&quot;, not %1</source>
        <comment>recipe.file.well_not_string</comment>
        <translation>必须是形如“A1”或“A1:H1”的字符串，而不是%1</translation>
    </message>
    <message>
        <source>must be a well set (&quot;A1:H1&quot;, &quot;row B&quot;, …) or a list of them, not %1</source>
        <comment>recipe.file.wells_wrong_type</comment>
        <translation>必须是孔集合（“A1:H1”、“row B”……）或其列表，而不是%1</translation>
    </message>
    <message>
        <source>unknown step type &quot;%1&quot;; the types are %2</source>
        <comment>recipe.file.unknown_step_type</comment>
        <translation>未知步骤类型“%1”；可用类型为 %2</translation>
    </message>
    <message>
        <source>a %1 step has no &quot;%2&quot;</source>
        <comment>recipe.file.field_of_other_step</comment>
        <translation>%1 步骤没有“%2”</translation>
    </message>
    <message>
        <source>needs a &quot;well&quot; (with its &quot;plate&quot;) or a &quot;station&quot;</source>
        <comment>recipe.file.source_empty</comment>
        <translation>需要“well”（及其“plate”）或“station”</translation>
    </message>
    <message>
        <source>at most %1 plates</source>
        <comment>recipe.file.too_many_plates</comment>
        <translation>最多 %1 块孔板</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <comment>recipe.where.well</comment>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>station %1</source>
        <comment>recipe.where.station</comment>
        <translation>工位 %1</translation>
    </message>
    <message>
        <source>aspirate %1 from %2</source>
        <comment>recipe.op.aspirate</comment>
        <translation>从 %2 吸液 %1</translation>
    </message>
    <message>
        <source>dispense %1 into %2</source>
        <comment>recipe.op.dispense</comment>
        <translation>向 %2 排液 %1</translation>
    </message>
    <message>
        <source>mix %1 in %2</source>
        <comment>recipe.op.mix</comment>
        <translation>在 %2 混匀 %1</translation>
    </message>
    <message>
        <source>wash %1 at %2</source>
        <comment>recipe.op.wash</comment>
        <translation>在 %2 清洗 %1</translation>
    </message>
    <message>
        <source>air gap %1</source>
        <comment>recipe.op.air_gap</comment>
        <translation>吸入空气间隔 %1</translation>
    </message>
    <message>
        <source>wait %1</source>
        <comment>recipe.op.wait</comment>
        <translation>等待 %1</translation>
    </message>
    <message>
        <source>touch off in %1</source>
        <comment>recipe.op.touch_off</comment>
        <translation>在 %1 贴壁</translation>
    </message>
    <message>
        <source>the run</source>
        <comment>recipe.run.the_run</comment>
        <translation>本次运行</translation>
    </message>
    <message>
        <source>the end</source>
        <comment>recipe.run.the_end</comment>
        <translation>结尾</translation>
    </message>
    <message>
        <source>a run is under way: abort it before changing the recipe</source>
        <comment>recipe.run.busy_changing</comment>
        <translation>运行正在进行：请先中止，再更改方案</translation>
    </message>
    <message>
        <source>the recipe does not validate: %1: %2</source>
        <comment>recipe.run.does_not_validate</comment>
        <translation>方案未通过检查：%1：%2</translation>
    </message>
    <message>
        <source>the analyzer is not connected</source>
        <comment>recipe.run.not_connected</comment>
        <translation>分析仪未连接</translation>
    </message>
    <message>
        <source>recipes run on the analyzer (axes X, Y, Z and the pump P); this is the %1</source>
        <comment>recipe.run.not_an_analyzer</comment>
        <translation>加样方案只能在分析仪上运行（X、Y、Z 轴和泵 P）；当前仪器是%1</translation>
    </message>
    <message>
        <source>the E-stop is latched: reset it before running</source>
        <comment>recipe.run.estop_latched</comment>
        <translation>急停已锁定：请先复位再运行</translation>
    </message>
    <message>
        <source>axis %1 is not homed: home the analyzer first (a recipe moves to absolute positions)</source>
        <comment>recipe.run.not_homed</comment>
        <translation>%1 轴尚未回零：请先让分析仪回零（方案要移动到绝对位置）</translation>
    </message>
    <message>
        <source>the analyzer is still moving: wait until it is still</source>
        <comment>recipe.run.still_moving</comment>
        <translation>分析仪仍在运动：请等待其停稳</translation>
    </message>
    <message>
        <source>%1: (%2, %3) is beyond the soft limits X %4–%5, Y %6–%7</source>
        <comment>recipe.run.xy_beyond_limits</comment>
        <translation>%1：（%2, %3）超出软限位 X %4–%5、Y %6–%7</translation>
    </message>
    <message>
        <source>%1: Z %2 is beyond the soft limits %3–%4</source>
        <comment>recipe.run.z_beyond_limits</comment>
        <translation>%1：Z %2 超出软限位 %3–%4</translation>
    </message>
    <message>
        <source>the plunger would travel %1–%2 (it is at %3), beyond its limits %4–%5: empty the syringe first</source>
        <comment>recipe.run.plunger_beyond_limits_full</comment>
        <translation>柱塞将运行到 %1–%2（当前在 %3），超出其限位 %4–%5：请先排空注射器</translation>
    </message>
    <message>
        <source>the plunger would travel %1–%2 (it is at %3), beyond its limits %4–%5: the recipe dispenses more than it aspirates</source>
        <comment>recipe.run.plunger_beyond_limits_empty</comment>
        <translation>柱塞将运行到 %1–%2（当前在 %3），超出其限位 %4–%5：方案排出的液体多于吸入的</translation>
    </message>
    <message>
        <source>%1: the run stopped, since what it does could no longer be recorded</source>
        <comment>recipe.run.log_failed</comment>
        <translation>%1：运行已停止，因为其动作已无法记录</translation>
    </message>
    <message>
        <source>a run is already under way</source>
        <comment>recipe.run.already_running</comment>
        <translation>已有运行正在进行</translation>
    </message>
    <message>
        <source>no recipe to run</source>
        <comment>recipe.run.no_recipe</comment>
        <translation>没有可运行的方案</translation>
    </message>
    <message>
        <source>the analyzer refused a move of %1: %2</source>
        <comment>recipe.run.move_refused</comment>
        <translation>分析仪拒绝了“%1”中的一次移动：%2</translation>
    </message>
    <message>
        <source>aborted; the tip is up at Z %1</source>
        <comment>recipe.run.aborted_tip_up</comment>
        <translation>已中止；加样针已抬起到 Z %1</translation>
    </message>
    <message>
        <source>aborted; the tip could not be raised (E-stop or Z not homed)</source>
        <comment>recipe.run.aborted_tip_down</comment>
        <translation>已中止；加样针无法抬起（急停或 Z 轴未回零）</translation>
    </message>
    <message>
        <source>aborted by the operator while paused</source>
        <comment>recipe.run.aborted_while_paused</comment>
        <translation>暂停期间由操作员中止</translation>
    </message>
    <message>
        <source>paused after %1; Resume continues with the next well</source>
        <comment>recipe.run.paused_after</comment>
        <translation>在“%1”之后暂停；按“继续”从下一个孔接着运行</translation>
    </message>
    <message>
        <source>E-stop: the run stopped at %1. Reset the E-stop, check the machine, then Resume</source>
        <comment>recipe.run.estop</comment>
        <translation>急停：运行停在“%1”。请复位急停、检查设备，然后按“继续”</translation>
    </message>
    <message>
        <source>%1 (%2): the run stopped; re-home before resuming</source>
        <comment>recipe.run.fault</comment>
        <translation>%1（%2）：运行已停止；继续之前请重新回零</translation>
    </message>
    <message>
        <source>%1 (%2) during %3</source>
        <comment>recipe.run.event_during</comment>
        <translation>“%3”期间发生%1（%2）</translation>
    </message>
    <message>
        <source>no MotionDone arrived for a %1 move, but the status shows it completed: going on</source>
        <comment>recipe.run.motion_done_lost</comment>
        <translation>%1移动没有收到 MotionDone，但状态显示已完成：继续运行</translation>
    </message>
    <message>
        <source>the analyzer did not finish a %1 move of %2 in time</source>
        <comment>recipe.run.move_timeout</comment>
        <translation>分析仪未能按时完成“%2”中的%1移动</translation>
    </message>
    <message>
        <source>the analyzer is back: Resume continues with %1</source>
        <comment>recipe.run.back</comment>
        <translation>分析仪已恢复连接：按“继续”从“%1”接着运行</translation>
    </message>
    <message>
        <source>the link to the analyzer was lost during %1: the run stopped (the analyzer completes the move it had). Reconnect, then Resume</source>
        <comment>recipe.run.link_lost</comment>
        <translation>在“%1”期间与分析仪的连接中断：运行已停止（分析仪会完成正在执行的移动）。请重新连接，然后按“继续”</translation>
    </message>
    <message>
        <source>%1 was interrupted after liquid started to move (%2): say whether to skip it or do it again</source>
        <comment>recipe.run.interrupted_needs_decision</comment>
        <translation>“%1”在液体开始移动后被中断（%2）：请决定跳过还是重做</translation>
    </message>
    <message>
        <source>not resumed: %1 was interrupted and no decision was made</source>
        <comment>recipe.run.not_resumed_no_decision</comment>
        <translation>未继续：“%1”被中断且未作决定</translation>
    </message>
    <message>
        <source>%1 will be done again</source>
        <comment>recipe.run.will_redo</comment>
        <translation>“%1”将重做</translation>
    </message>
    <message>
        <source>%1 counts as done (skipped on resume)</source>
        <comment>recipe.run.counts_as_done</comment>
        <translation>“%1”视为已完成（继续时跳过）</translation>
    </message>
    <message>
        <source>nothing to resume</source>
        <comment>recipe.run.nothing_to_resume</comment>
        <translation>没有可继续的运行</translation>
    </message>
    <message>
        <source>the run log is closed: resume from the log file instead</source>
        <comment>recipe.run.log_closed</comment>
        <translation>运行日志已关闭：请改为从日志文件继续</translation>
    </message>
    <message>
        <source>%1 cannot be trusted to resume from: line %2: %3</source>
        <comment>recipe.run.log_untrusted</comment>
        <translation>%1 不可信，不能据此继续：第 %2 行：%3</translation>
    </message>
    <message>
        <source>%1 is the log of another recipe, or of this one before it changed (%2 ops, plan %3; this recipe: %4 ops, plan %5)</source>
        <comment>recipe.run.log_of_other_recipe</comment>
        <translation>%1 是另一个方案的日志，或是本方案修改前的日志（%2 个操作，计划 %3；本方案：%4 个操作，计划 %5）</translation>
    </message>
    <message>
        <source>the run in %1 finished: nothing to resume</source>
        <comment>recipe.run.log_finished</comment>
        <translation>%1 中的运行已完成：没有可继续的内容</translation>
    </message>
    <message>
        <source>the plunger is at %1 but the log&apos;s last completed well left it at %2: the syringe was moved (or the analyzer restarted) since the run stopped, so what it holds is unknown. Start a new run.</source>
        <comment>recipe.run.plunger_moved</comment>
        <translation>柱塞在 %1，但日志中最后完成的孔使其停在 %2：运行停止后注射器被移动过（或分析仪重启过），其中的液量未知。请开始新的运行。</translation>
    </message>
    <message>
        <source>the plunger is at %1, where this step leaves it: its liquid most likely moved in full</source>
        <comment>recipe.evidence.moved_in_full</comment>
        <translation>柱塞在 %1，正是该步骤完成后的位置：液体很可能已全部移动</translation>
    </message>
    <message>
        <source>the plunger is at %1, where it was before the pump move: no liquid moved</source>
        <comment>recipe.evidence.nothing_moved</comment>
        <translation>柱塞在 %1，与泵动作之前相同：没有液体移动</translation>
    </message>
    <message>
        <source>the plunger is at %1, between %2 (before) and %3 (after): part of the volume moved</source>
        <comment>recipe.evidence.part_moved</comment>
        <translation>柱塞在 %1，介于 %2（之前）与 %3（之后）之间：部分液体已移动</translation>
    </message>
    <message>
        <source>a %1 ends where it starts: the plunger cannot tell how far it got</source>
        <comment>recipe.evidence.cannot_tell</comment>
        <translation>%1结束时回到起始位置：无法从柱塞位置判断进行到了哪一步</translation>
    </message>
    <message>
        <source>idle</source>
        <comment>recipe.state.idle</comment>
        <translation>空闲</translation>
    </message>
    <message>
        <source>running</source>
        <comment>recipe.state.running</comment>
        <translation>运行中</translation>
    </message>
    <message>
        <source>pausing after this well</source>
        <comment>recipe.state.pausing</comment>
        <translation>本孔完成后暂停</translation>
    </message>
    <message>
        <source>paused</source>
        <comment>recipe.state.paused</comment>
        <translation>已暂停</translation>
    </message>
    <message>
        <source>aborting</source>
        <comment>recipe.state.aborting</comment>
        <translation>正在中止</translation>
    </message>
    <message>
        <source>stopped</source>
        <comment>recipe.state.stopped</comment>
        <translation>已停止</translation>
    </message>
    <message>
        <source>finished</source>
        <comment>recipe.state.finished</comment>
        <translation>已完成</translation>
    </message>
    <message>
        <source>raise</source>
        <comment>recipe.move.raise</comment>
        <translation>抬起</translation>
    </message>
    <message>
        <source>travel</source>
        <comment>recipe.move.travel</comment>
        <translation>平移</translation>
    </message>
    <message>
        <source>lower</source>
        <comment>recipe.move.lower</comment>
        <translation>下降</translation>
    </message>
    <message>
        <source>pump</source>
        <comment>recipe.move.pump</comment>
        <translation>泵</translation>
    </message>
    <message>
        <source>touch</source>
        <comment>recipe.move.touch</comment>
        <translation>贴壁</translation>
    </message>
    <message>
        <source>dwell</source>
        <comment>recipe.move.dwell</comment>
        <translation>停留</translation>
    </message>
    <message>
        <source>aspirate</source>
        <comment>recipe.step.aspirate</comment>
        <translation>吸液</translation>
    </message>
    <message>
        <source>dispense</source>
        <comment>recipe.step.dispense</comment>
        <translation>排液</translation>
    </message>
    <message>
        <source>mix</source>
        <comment>recipe.step.mix</comment>
        <translation>混匀</translation>
    </message>
    <message>
        <source>wash</source>
        <comment>recipe.step.wash</comment>
        <translation>清洗</translation>
    </message>
    <message>
        <source>air gap</source>
        <comment>recipe.step.air_gap</comment>
        <translation>空气间隔</translation>
    </message>
    <message>
        <source>wait</source>
        <comment>recipe.step.wait</comment>
        <translation>等待</translation>
    </message>
    <message>
        <source>touch-off</source>
        <comment>recipe.step.touch_off</comment>
        <translation>贴壁</translation>
    </message>
    <message>
        <source>aborted by the operator</source>
        <comment>recipe.run.aborted</comment>
        <translation>由操作员中止</translation>
    </message>
    <message>
        <source>the operator chose to do the interrupted op again</source>
        <comment>recipe.run.operator_redo</comment>
        <translation>操作员选择重做被中断的操作</translation>
    </message>
    <message>
        <source>the operator counted the interrupted op as done</source>
        <comment>recipe.run.operator_skip</comment>
        <translation>操作员将被中断的操作视为已完成</translation>
    </message>
    <message>
        <source>this is not the instrument the run was on (%1; now %2): resume it on that one, or start the run again</source>
        <comment>recipe.resume.other_instrument</comment>
        <translation>这不是运行所在的仪器（%1；现在是 %2）：请在原仪器上继续，或重新开始运行</translation>
    </message>
    <message>
        <source>found the same instrument (%1), homed, with the plunger at %2 as the run left it</source>
        <comment>recipe.resume.found</comment>
        <translation>找到同一台仪器（%1），已回零，柱塞在 %2，与运行停止时一致</translation>
    </message>
    <message numerus="yes">
        <source>running %1: %Ln operations, about %2; log %3</source>
        <comment>recipe.run.started</comment>
        <translation>
            <numerusform>正在运行 %1：%Ln 项操作，约 %2；日志 %3</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1 finished: %Ln operations</source>
        <comment>recipe.run.finished</comment>
        <translation>
            <numerusform>%1 已完成：%Ln 项操作</numerusform>
        </translation>
    </message>
    <message>
        <source>resuming %1 from %2: %3 of %4 operations already done, continuing with %5</source>
        <comment>recipe.run.resuming</comment>
        <translation>从 %2 继续 %1：%4 项操作中已完成 %3 项，接着运行“%5”</translation>
    </message>
    <message>
        <source>a clearance counts up from the labware&apos;s top: %1 is not from 0 to %2</source>
        <comment>recipe.clearance_below_top</comment>
        <translation>安全间隙从耗材顶面向上计：%1 不在 0 到 %2 之间</translation>
    </message>
    <message>
        <source>&quot;travel&quot; needs a recipe of version 2 (this one is version %1)</source>
        <comment>recipe.file.travel_needs_version</comment>
        <translation>“travel” 需要第 2 版方案（本方案为第 %1 版）</translation>
    </message>
    <message>
        <source>unknown travel mode &quot;%1&quot;; the modes are arched, straight-up-down</source>
        <comment>recipe.file.unknown_travel_mode</comment>
        <translation>未知移动方式 “%1”；可用方式为 arched、straight-up-down</translation>
    </message>
    <message>
        <source>one well&apos;s %1 with the disposal volume %2 and the air gap %3 does not fit the syringe&apos;s room (%4)</source>
        <comment>recipe.distribute_no_room</comment>
        <translation>一个孔的 %1 加上弃液量 %2 和空气间隔 %3 超出注射器的剩余容量（%4）</translation>
    </message>
    <message>
        <source>distributing needs a source to draw from</source>
        <comment>recipe.distribute_needs_source</comment>
        <translation>分配需要一个吸液来源</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is for a step that distributes: add &quot;distribute&quot;: true</source>
        <comment>recipe.needs_distribute</comment>
        <translation>“%1” 用于分配步骤：请加上 “distribute”: true</translation>
    </message>
    <message>
        <source>a step at a station has no wells to put in order &quot;%1&quot;</source>
        <comment>recipe.order_without_wells</comment>
        <translation>工位上的步骤没有可按 “%1” 排序的孔</translation>
    </message>
    <message>
        <source>unknown well order &quot;%1&quot;; the orders are %2</source>
        <comment>recipe.file.unknown_order</comment>
        <translation>未知孔顺序 “%1”；可用顺序为 %2</translation>
    </message>
</context>
<context>
    <name>ui::words::RefusalWords</name>
    <message>
        <source>the device does not know this request (type %1)</source>
        <comment>device.refused.unknown_command</comment>
        <translation>设备不认识此请求（类型 %1）</translation>
    </message>
    <message>
        <source>the device could not read this request</source>
        <comment>device.refused.bad_payload</comment>
        <translation>设备无法读取此请求</translation>
    </message>
    <message>
        <source>the instrument has no axis or channel %1</source>
        <comment>device.refused.bad_axis</comment>
        <translation>仪器没有轴或通道 %1</translation>
    </message>
    <message>
        <source>still moving or homing</source>
        <comment>device.refused.busy</comment>
        <translation>仍在运动或回零</translation>
    </message>
    <message>
        <source>the E-stop is latched: reset it first</source>
        <comment>device.refused.estop_active</comment>
        <translation>急停已锁定：请先复位</translation>
    </message>
    <message>
        <source>the telemetry would not fit the link: at most %1 fits</source>
        <comment>device.refused.over_capacity</comment>
        <translation>遥测超出链路容量：最多可容纳 %1</translation>
    </message>
    <message>
        <source>a speed, limit, rate or count in the request is out of the device&apos;s range</source>
        <comment>device.refused.out_of_range</comment>
        <translation>请求中的速度、限值、速率或数量超出设备范围</translation>
    </message>
    <message>
        <source>the device is in a fault state: reset it first</source>
        <comment>device.refused.fault</comment>
        <translation>设备处于故障状态：请先复位</translation>
    </message>
    <message>
        <source>gain %1 is not finite, is negative or is above the device&apos;s limit; nothing changed</source>
        <comment>device.refused.bad_gains</comment>
        <translation>增益 %1 不是有限值、为负或超过设备上限；未作任何更改</translation>
    </message>
    <message>
        <source>a tuning test runs on it</source>
        <comment>device.refused.test_active</comment>
        <translation>该轴正在运行整定测试</translation>
    </message>
    <message>
        <source>it has no closed loop (PID) to tune</source>
        <comment>device.refused.not_closed_loop</comment>
        <translation>该轴没有可整定的闭环（PID）</translation>
    </message>
    <message>
        <source>no test capture to read there (%1 samples captured)</source>
        <comment>device.refused.no_capture</comment>
        <translation>该处没有可读取的测试采集数据（已采集 %1 个样本）</translation>
    </message>
    <message>
        <source>the path queue has room for only %1 more segments</source>
        <comment>device.refused.path_queue_full</comment>
        <translation>路径队列只能再容纳 %1 段</translation>
    </message>
    <message>
        <source>the device expected path segment %1 next</source>
        <comment>device.refused.path_sequence</comment>
        <translation>设备期望的下一段是第 %1 段</translation>
    </message>
    <message>
        <source>path segment %1 cannot be run: an arc&apos;s end is off its circle, or its radius is under two steps</source>
        <comment>device.refused.path_geometry</comment>
        <translation>第 %1 段无法执行：圆弧终点不在圆上，或半径小于两步</translation>
    </message>
    <message>
        <source>no path is open to add to: none was begun, its last segment is queued, or it was aborted</source>
        <comment>device.refused.path_state</comment>
        <translation>没有可追加的路径：未开始路径、最后一段已入队，或路径已中止</translation>
    </message>
    <message>
        <source>the device cannot apply this compensation; nothing changed</source>
        <comment>device.refused.comp_invalid</comment>
        <translation>设备无法应用此补偿；未作任何更改</translation>
    </message>
    <message>
        <source>the compensation upload is out of order: the device expects entry %1</source>
        <comment>device.refused.comp_sequence</comment>
        <translation>补偿上传顺序错误：设备期望第 %1 项</translation>
    </message>
    <message>
        <source>no compensation to enable</source>
        <comment>device.refused.comp_missing</comment>
        <translation>没有可启用的补偿</translation>
    </message>
    <message>
        <source>axis %1: %2</source>
        <comment>device.refused.on_axis</comment>
        <translation>%1 轴：%2</translation>
    </message>
    <message>
        <source>%1 (the device says: %2)</source>
        <comment>device.refused.device_says</comment>
        <translation>%1</translation>
    </message>
    <message>
        <source>not homed: home it first</source>
        <comment>device.refused.not_homed</comment>
        <translation>未回零：请先回零</translation>
    </message>
    <message>
        <source>it would cross the soft limit at %1</source>
        <comment>device.refused.soft_limit</comment>
        <translation>将越过软限位 %1</translation>
    </message>
</context>
<context>
    <name>ui::words::ScanWords</name>
    <message>
        <source>must be from %1 to %2 (got %3)</source>
        <comment>scan.out_of_range</comment>
        <translation>必须在 %1 到 %2 之间（当前为 %3）</translation>
    </message>
    <message>
        <source>must be above 0 and at most %1 (got %2)</source>
        <comment>scan.not_positive_or_above</comment>
        <translation>必须大于 0 且不大于 %1（当前为 %2）</translation>
    </message>
    <message>
        <source>must be a finite position in mm</source>
        <comment>scan.not_a_position</comment>
        <translation>必须是以 mm 为单位的有限位置</translation>
    </message>
    <message>
        <source>the region has zero size (%1 × %2): the corners must differ in both X and Y</source>
        <comment>scan.region.corners_zero_size</comment>
        <translation>区域大小为零（%1 × %2）：两个角点的 X 和 Y 都必须不同</translation>
    </message>
    <message>
        <source>the region has zero size (%1 × %2): width and height must be above 0</source>
        <comment>scan.region.size_zero</comment>
        <translation>区域大小为零（%1 × %2）：宽度和高度都必须大于 0</translation>
    </message>
    <message>
        <source>at most %1 vertices (got %2)</source>
        <comment>scan.region.too_many_vertices</comment>
        <translation>最多 %1 个顶点（当前 %2 个）</translation>
    </message>
    <message>
        <source>the polygon has zero area</source>
        <comment>scan.region.zero_area</comment>
        <translation>多边形面积为零</translation>
    </message>
    <message>
        <source>the outline crosses or touches itself; draw it without crossings</source>
        <comment>scan.region.self_intersecting</comment>
        <translation>轮廓自相交或自相接；请画成无交叉的轮廓</translation>
    </message>
    <message>
        <source>the field at the sample must be at least %1 each way (got %2 × %3)</source>
        <comment>scan.camera.field_too_small</comment>
        <translation>样品处的视场每个方向至少为 %1（当前 %2 × %3）</translation>
    </message>
    <message>
        <source>must be from 0 to %1, a share of the field (got %2)</source>
        <comment>scan.overlap_out_of_range</comment>
        <translation>必须在 0 到 %1 之间，即占视场的比例（当前为 %2）</translation>
    </message>
    <message>
        <source>must hold 1 to 6 finite coefficients, constant term first</source>
        <comment>scan.compensation.bad_coefficients</comment>
        <translation>必须包含 1 到 6 个有限系数，常数项在前</translation>
    </message>
    <message>
        <source>the curve reaches %1 over the region; a positioning error above %2 is not one to compensate</source>
        <comment>scan.compensation.curve_too_large</comment>
        <translation>该曲线在区域内达到 %1；超过 %2 的定位误差不属于可补偿的范围</translation>
    </message>
    <message>
        <source>must name Micro-Manager&apos;s XY stage device (not empty, one line)</source>
        <comment>scan.export.bad_stage_name</comment>
        <translation>必须填写 Micro-Manager 的 XY 载物台设备名（不能为空，只能一行）</translation>
    </message>
    <message>
        <source>the field is so small for the region that the grid would have %1 tiles (at most %2)</source>
        <comment>scan.too_many_tiles</comment>
        <translation>相对于区域而言视场太小，网格将有 %1 个图块（最多 %2 个）</translation>
    </message>
    <message>
        <source>the field is so small for the region that the grid would have over %1 tiles (at most %1)</source>
        <comment>scan.too_many_tiles_over</comment>
        <translation>相对于区域而言视场太小，网格将超过 %1 个图块（最多 %1 个）</translation>
    </message>
    <message>
        <source>the field %1 × %2 is larger than the stage&apos;s travel %3 × %4</source>
        <comment>scan.field_larger_than_travel</comment>
        <translation>视场 %1 × %2 大于载物台行程 %3 × %4</translation>
    </message>
    <message>
        <source>the region X %1 … %2, Y %3 … %4 reaches beyond the stage&apos;s travel X %5 … %6, Y %7 … %8</source>
        <comment>scan.region_beyond_travel</comment>
        <translation>区域 X %1 … %2、Y %3 … %4 超出载物台行程 X %5 … %6、Y %7 … %8</translation>
    </message>
    <message>
        <source>must be at most the stage&apos;s top speed %1 (got %2)</source>
        <comment>scan.speed_above_stage</comment>
        <translation>不能超过载物台的最高速度 %1（当前为 %2）</translation>
    </message>
    <message>
        <source>tile %1 (%2, %3) lies outside the stage&apos;s travel X %4 … %5, Y %6 … %7; move the region inward</source>
        <comment>scan.tile_outside_travel</comment>
        <translation>图块 %1（%2, %3）位于载物台行程 X %4 … %5、Y %6 … %7 之外；请把区域向内移</translation>
    </message>
    <message>
        <source>the overtravel point before tile %1 (%2, %3) lies outside the stage&apos;s travel X %4 … %5, Y %6 … %7; move the region inward</source>
        <comment>scan.overtravel_outside_travel</comment>
        <translation>图块 %1 之前的超程点（%2, %3）位于载物台行程 X %4 … %5、Y %6 … %7 之外；请把区域向内移</translation>
    </message>
    <message>
        <source>must hold two opposite corners [[x, y], [x, y]]</source>
        <comment>scan.file.two_corners</comment>
        <translation>必须包含两个对角点 [[x, y], [x, y]]</translation>
    </message>
    <message>
        <source>must not be empty</source>
        <comment>scan.naming.empty</comment>
        <translation>不能为空</translation>
    </message>
    <message>
        <source>must not start or end with a space (Fiji trims file names)</source>
        <comment>scan.naming.edge_space</comment>
        <translation>首尾不能有空格（Fiji 会去掉文件名首尾的空格）</translation>
    </message>
    <message>
        <source>must not start with &apos;#&apos; (Fiji reads such a line as a comment)</source>
        <comment>scan.naming.starts_with_hash</comment>
        <translation>不能以“#”开头（Fiji 会把这样的行当作注释）</translation>
    </message>
    <message>
        <source>must not contain &apos;;&apos; (it separates the fields of a TileConfiguration line)</source>
        <comment>scan.naming.semicolon</comment>
        <translation>不能含有“;”（它用于分隔 TileConfiguration 行中的字段）</translation>
    </message>
    <message>
        <source>must be a file name without a folder (&apos;/&apos; or &apos;\&apos;)</source>
        <comment>scan.naming.folder</comment>
        <translation>必须是不含文件夹的文件名（不能有“/”或“\”）</translation>
    </message>
    <message>
        <source>must not contain control characters or line breaks</source>
        <comment>scan.naming.control_character</comment>
        <translation>不能含有控制字符或换行</translation>
    </message>
    <message>
        <source>&apos;{&apos; at character %1 is never closed</source>
        <comment>scan.naming.unclosed_brace</comment>
        <translation>第 %1 个字符处的“{”没有闭合</translation>
    </message>
    <message>
        <source>&apos;}&apos; at character %1 has no &apos;{&apos;</source>
        <comment>scan.naming.unopened_brace</comment>
        <translation>第 %1 个字符处的“}”没有对应的“{”</translation>
    </message>
    <message>
        <source>unknown placeholder %1; use {i}, {row} or {col}, optionally padded as {i:03}</source>
        <comment>scan.naming.unknown_placeholder</comment>
        <translation>未知的占位符 %1；请使用 {i}、{row} 或 {col}，可补零写作 {i:03}</translation>
    </message>
    <message>
        <source>placeholder %1: the width must look like :03 (a zero and one digit)</source>
        <comment>scan.naming.bad_width</comment>
        <translation>占位符 %1：宽度应写作 :03（一个零加一位数字）</translation>
    </message>
    <message>
        <source>must contain {i}, or both {row} and {col}, so every tile gets its own file</source>
        <comment>scan.naming.no_index</comment>
        <translation>必须含有 {i}，或同时含有 {row} 和 {col}，使每个图块对应一个文件</translation>
    </message>
    <message>
        <source>tile %1 of %2 (%3)</source>
        <comment>scan.run.tile</comment>
        <translation>第 %1 个图块（共 %2 个，%3）</translation>
    </message>
    <message>
        <source>the start</source>
        <comment>scan.run.the_start</comment>
        <translation>起点</translation>
    </message>
    <message>
        <source>%1 did not settle within %2 in %3 (X off by %4, Y by %5); the run is stopped: check the stage, then Resume to try this tile again</source>
        <comment>scan.run.not_settled</comment>
        <translation>%1 在 %3 内未稳定到 %2 以内（X 偏差 %4，Y 偏差 %5）；扫描已停止：请检查载物台，然后按“继续”重试该图块</translation>
    </message>
    <message>
        <source>The link to the stage was lost at %1. Nothing more moves from here; reconnect, then Resume to continue at that tile.</source>
        <comment>scan.run.link_lost</comment>
        <translation>在%1处与载物台的连接中断。此后不会再有任何运动；请重新连接，然后按“继续”从该图块接着扫描。</translation>
    </message>
    <message>
        <source>The link to the stage was lost at %1 (%2). Nothing more moves from here; reconnect, then Resume to continue at that tile.</source>
        <comment>scan.run.link_lost_cause</comment>
        <translation>在%1处与载物台的连接中断（%2）。此后不会再有任何运动；请重新连接，然后按“继续”从该图块接着扫描。</translation>
    </message>
    <message>
        <source>A scan is running: stop it before preparing another.</source>
        <comment>scan.run.busy_preparing</comment>
        <translation>扫描正在进行：请先停止，再准备新的扫描。</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <comment>scan.run.plan_problem</comment>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>The run log %1 in this folder is damaged at line %2 (%3); it is left as it is.</source>
        <comment>scan.run.log_damaged</comment>
        <translation>此文件夹中的运行日志 %1 在第 %2 行损坏（%3）；日志保持原样。</translation>
    </message>
    <message>
        <source>This folder holds the run log of a different scan (%1 of %2 tiles taken). Choose another folder, or start over to keep that log aside and begin a new one.</source>
        <comment>scan.run.other_scans_log</comment>
        <translation>此文件夹中是另一次扫描的运行日志（已采集 %1/%2 个图块）。请选择其他文件夹，或重新开始：旧日志将另存，再开始新的日志。</translation>
    </message>
    <message>
        <source>Cannot move the old run log aside to %1.</source>
        <comment>scan.run.cannot_move_log</comment>
        <translation>无法把旧运行日志另存为 %1。</translation>
    </message>
    <message>
        <source>No scan is prepared.</source>
        <comment>scan.run.not_prepared</comment>
        <translation>尚未准备扫描。</translation>
    </message>
    <message>
        <source>The stage is not connected.</source>
        <comment>scan.run.not_connected</comment>
        <translation>载物台未连接。</translation>
    </message>
    <message>
        <source>Scans run on the microscope stage; this instrument is the %1.</source>
        <comment>scan.run.not_a_stage</comment>
        <translation>扫描只能在显微镜载物台上运行；当前仪器是%1。</translation>
    </message>
    <message>
        <source>The E-stop is latched: reset it first.</source>
        <comment>scan.run.estop_latched</comment>
        <translation>急停已锁定：请先复位。</translation>
    </message>
    <message>
        <source>Home the stage first: a scan moves to absolute positions.</source>
        <comment>scan.run.not_homed</comment>
        <translation>请先让载物台回零：扫描要移动到绝对位置。</translation>
    </message>
    <message>
        <source>The scan is already running.</source>
        <comment>scan.run.already_running</comment>
        <translation>扫描已在运行。</translation>
    </message>
    <message>
        <source>Aborted at %1. The tiles taken so far are kept; Resume continues at that tile.</source>
        <comment>scan.run.aborted</comment>
        <translation>在%1处中止。已采集的图块都会保留；按“继续”从该图块接着扫描。</translation>
    </message>
    <message>
        <source>Every tile is taken, but the exports could not be written: %1</source>
        <comment>scan.run.exports_failed</comment>
        <translation>所有图块均已采集，但导出文件无法写入：%1</translation>
    </message>
    <message>
        <source>The stage refused the move to %1: %2</source>
        <comment>scan.run.move_refused</comment>
        <translation>载物台拒绝移动到%1：%2</translation>
    </message>
    <message>
        <source>E-stop at %1: the run is stopped. Reset the E-stop and Resume to continue at that tile.</source>
        <comment>scan.run.estop</comment>
        <translation>在%1处急停：扫描已停止。复位急停后按“继续”从该图块接着扫描。</translation>
    </message>
    <message>
        <source>The stage reported &quot;%1&quot; (%2) at %3: the run is stopped. Resume continues at that tile.</source>
        <comment>scan.run.stage_event</comment>
        <translation>载物台在%3处报告“%1”（%2）：扫描已停止。按“继续”从该图块接着扫描。</translation>
    </message>
    <message>
        <source>%1 The run is stopped so that no tile goes unrecorded.</source>
        <comment>scan.run.log_failed</comment>
        <translation>%1 扫描已停止，以免有图块未被记录。</translation>
    </message>
    <message>
        <source>ready</source>
        <comment>scan.state.idle</comment>
        <translation>就绪</translation>
    </message>
    <message>
        <source>running</source>
        <comment>scan.state.running</comment>
        <translation>运行中</translation>
    </message>
    <message>
        <source>pausing after this tile</source>
        <comment>scan.state.pausing</comment>
        <translation>本图块完成后暂停</translation>
    </message>
    <message>
        <source>paused</source>
        <comment>scan.state.paused</comment>
        <translation>已暂停</translation>
    </message>
    <message>
        <source>stopped</source>
        <comment>scan.state.stopped</comment>
        <translation>已停止</translation>
    </message>
    <message>
        <source>finished</source>
        <comment>scan.state.finished</comment>
        <translation>已完成</translation>
    </message>
    <message numerus="yes">
        <source>a polygon needs at least 3 vertices (got %Ln)</source>
        <comment>scan.region.too_few_vertices</comment>
        <translation>
            <numerusform>多边形至少需要 3 个顶点（当前 %Ln 个）</numerusform>
        </translation>
    </message>
    <message>
        <source>The plan runs with the stage&apos;s own compensation, but this stage keeps none: run without it.</source>
        <comment>scan.run.no_compensation_on_stage</comment>
        <translation>本方案依赖载物台自身的误差补偿，但该载物台没有补偿数据：请不使用补偿运行。</translation>
    </message>
    <message>
        <source>Reading whether the stage&apos;s compensation of %1 is enabled…</source>
        <comment>scan.run.compensation_being_read</comment>
        <translation>正在读取载物台 %1 轴的补偿是否已启用…</translation>
    </message>
    <message>
        <source>The plan runs with the stage&apos;s own compensation, but it is not enabled on %1: enable it (Calibration screen, or compensation enable --axis %1), or run without it.</source>
        <comment>scan.run.compensation_not_enabled</comment>
        <translation>本方案依赖载物台自身的误差补偿，但 %1 轴未启用补偿：请启用（在“校准”界面，或 compensation enable --axis %1），或不使用补偿运行。</translation>
    </message>
    <message>
        <source>The camera could not take %1: %2 The run is stopped; every tile taken before it is kept. Resume takes this tile again.</source>
        <comment>scan.run.camera_failed</comment>
        <translation>相机无法拍摄%1：%2 运行已停止；之前拍摄的每个图块都已保留。继续运行时会重拍此图块。</translation>
    </message>
    <message>
        <source>the camera %1 gave no image within %2 after the exposure</source>
        <comment>scan.run.camera_silent</comment>
        <translation>相机 %1 在曝光结束后 %2 内没有给出图像</translation>
    </message>
    <message>
        <source>a stitch is already running</source>
        <comment>scan.stitch.running</comment>
        <translation>已有一个拼接正在进行</translation>
    </message>
    <message>
        <source>%1 holds no scan run log: run a scan with images into it first</source>
        <comment>scan.stitch.no_run_log</comment>
        <translation>%1 中没有扫描运行日志：请先把一次带图像的扫描运行到该文件夹</translation>
    </message>
    <message>
        <source>the scan in %1 took no images to stitch (was “Take an image at each tile” on?)</source>
        <comment>scan.stitch.no_images</comment>
        <translation>%1 中的扫描没有拍摄可拼接的图像（是否勾选了“在每个图块拍摄图像”？）</translation>
    </message>
    <message>
        <source>the image of tile %2 (%1) is not in the folder</source>
        <comment>scan.stitch.image_missing</comment>
        <translation>图块 %2 的图像（%1）不在该文件夹中</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <comment>scan.stitch.cannot_write</comment>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>trusted</source>
        <comment>scan.pair.accepted</comment>
        <translation>可信</translation>
    </message>
    <message>
        <source>not trusted: score too low (blank, dark or out of focus)</source>
        <comment>scan.pair.low_score</comment>
        <translation>不可信：得分太低（空白、太暗或失焦）</translation>
    </message>
    <message>
        <source>not trusted: two offsets score alike (a repetitive pattern)</source>
        <comment>scan.pair.ambiguous</comment>
        <translation>不可信：两个偏移得分相近（重复图案）</translation>
    </message>
    <message>
        <source>not trusted: the best offset lies on the search bound</source>
        <comment>scan.pair.at_bound</comment>
        <translation>不可信：最佳偏移位于搜索边界上</translation>
    </message>
    <message>
        <source>not trusted: too little overlap</source>
        <comment>scan.pair.no_overlap</comment>
        <translation>不可信：重叠太少</translation>
    </message>
    <message>
        <source>rejected: disagrees with the other pairs</source>
        <comment>scan.pair.outlier</comment>
        <translation>已剔除：与其他图块对不一致</translation>
    </message>
    <message>
        <source>the camera profile %1, line %2, column %3: %4</source>
        <comment>scan.plan.camera_profile_problem</comment>
        <translation>相机配置文件 %1，第 %2 行，第 %3 列：%4</translation>
    </message>
</context>
<context>
    <name>ui::words::ShippedNames</name>
    <message>
        <source>back</source>
        <translation>后侧</translation>
    </message>
    <message>
        <source>front</source>
        <translation>前侧</translation>
    </message>
    <message>
        <source>wash trough</source>
        <translation>清洗槽</translation>
    </message>
    <message>
        <source>waste trough</source>
        <translation>废液槽</translation>
    </message>
    <message>
        <source>6-well plate, 16.8 mL</source>
        <translation>6 孔板，16.8 mL</translation>
    </message>
    <message>
        <source>12-well plate, 6.9 mL</source>
        <translation>12 孔板，6.9 mL</translation>
    </message>
    <message>
        <source>24-well plate, 3.4 mL</source>
        <translation>24 孔板，3.4 mL</translation>
    </message>
    <message>
        <source>48-well plate, 1.6 mL</source>
        <translation>48 孔板，1.6 mL</translation>
    </message>
    <message>
        <source>96-well plate, 360 µL</source>
        <translation>96 孔板，360 µL</translation>
    </message>
    <message>
        <source>384-well plate, 112 µL</source>
        <translation>384 孔板，112 µL</translation>
    </message>
</context>
<context>
    <name>ui::words::TuningWords</name>
    <message>
        <source>%1 is %2: a gain must be a finite number</source>
        <comment>tuning.gain_not_finite</comment>
        <translation>%1 为 %2：增益必须是有限数</translation>
    </message>
    <message>
        <source>%1 = %2 must not be negative</source>
        <comment>tuning.gain_negative</comment>
        <translation>%1 = %2 不能为负</translation>
    </message>
    <message>
        <source>%1 = %2 is above the largest accepted %3 per control period</source>
        <comment>tuning.gain_above_limit</comment>
        <translation>%1 = %2 超过每个控制周期允许的最大值 %3</translation>
    </message>
    <message>
        <source>unknown plant kind &apos;%1&apos;: use fopdt:K=..,tau=..,L=.. or lag:K=..,tau=..,n=..</source>
        <comment>tuning.plant.unknown_kind</comment>
        <translation>未知的对象类型“%1”：请用 fopdt:K=..,tau=..,L=.. 或 lag:K=..,tau=..,n=..</translation>
    </message>
    <message>
        <source>%1: no fields given (fields: %2)</source>
        <comment>tuning.plant.no_fields</comment>
        <translation>%1：没有给出参数（参数：%2）</translation>
    </message>
    <message>
        <source>%1: empty field (fields: %2)</source>
        <comment>tuning.plant.empty_field</comment>
        <translation>%1：有空参数（参数：%2）</translation>
    </message>
    <message>
        <source>%1: unknown field &apos;%2&apos; (fields: %3)</source>
        <comment>tuning.plant.unknown_field</comment>
        <translation>%1：未知参数“%2”（参数：%3）</translation>
    </message>
    <message>
        <source>%1: %2 has no value (write %2=NUMBER)</source>
        <comment>tuning.plant.no_value</comment>
        <translation>%1：%2 没有数值（请写成 %2=数值）</translation>
    </message>
    <message>
        <source>%1: %2 is given twice</source>
        <comment>tuning.plant.field_twice</comment>
        <translation>%1：%2 给出了两次</translation>
    </message>
    <message>
        <source>%1: %2 must be a number (got &apos;%3&apos;)</source>
        <comment>tuning.plant.not_a_number</comment>
        <translation>%1：%2 必须是数字（当前为“%3”）</translation>
    </message>
    <message>
        <source>%1: %2 is missing (fields: %3)</source>
        <comment>tuning.plant.field_missing</comment>
        <translation>%1：缺少 %2（参数：%3）</translation>
    </message>
    <message>
        <source>%1: %2 must be above 0 (got %3)</source>
        <comment>tuning.plant.not_positive</comment>
        <translation>%1：%2 必须大于 0（当前为 %3）</translation>
    </message>
    <message>
        <source>%1: %2 must not be negative (got %3)</source>
        <comment>tuning.plant.negative</comment>
        <translation>%1：%2 不能为负（当前为 %3）</translation>
    </message>
    <message>
        <source>%1: Ts must be above 0 and at most %2 (got %3)</source>
        <comment>tuning.plant.period_out_of_range</comment>
        <translation>%1：Ts 必须大于 0 且不大于 %2（当前为 %3）</translation>
    </message>
    <message>
        <source>%1: tau and L are both 0: that is a pure gain, not a plant to tune</source>
        <comment>tuning.plant.pure_gain</comment>
        <translation>%1：tau 和 L 都为 0：这是纯比例环节，不是可整定的对象</translation>
    </message>
    <message>
        <source>%1: L is more than 100000 control periods (L = %2, Ts = %3): use a longer Ts</source>
        <comment>tuning.plant.delay_too_long</comment>
        <translation>%1：L 超过 100000 个控制周期（L = %2，Ts = %3）：请用更长的 Ts</translation>
    </message>
    <message>
        <source>%1: n must be a whole number from 1 to 12 (got %2)</source>
        <comment>tuning.plant.order_invalid</comment>
        <translation>%1：n 必须是 1 到 12 的整数（当前为 %2）</translation>
    </message>
    <message>
        <source>a first-order plant without dead time never lags by 180°: P control cannot make it oscillate, so it has no finite ultimate gain</source>
        <comment>tuning.plant.first_order_no_ku</comment>
        <translation>无纯滞后的一阶对象相位滞后永远达不到 180°：比例控制无法使其振荡，因此不存在有限的临界增益</translation>
    </message>
    <message>
        <source>a lag of order %1 lags less than %2 at every frequency, never 180°: P control cannot make it oscillate, so it has no finite ultimate gain</source>
        <comment>tuning.plant.lag_no_ku</comment>
        <translation>%1 阶惯性环节在任何频率下相位滞后都小于 %2，达不到 180°：比例控制无法使其振荡，因此不存在有限的临界增益</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <comment>tuning.model.no_ultimate_gain</comment>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>Kp = %1: cycle ratio %2</source>
        <comment>tuning.progress.trial</comment>
        <translation>Kp = %1：周期幅值比 %2</translation>
    </message>
    <message>
        <source>Kp = %1: no oscillation</source>
        <comment>tuning.progress.trial_no_oscillation</comment>
        <translation>Kp = %1：未振荡</translation>
    </message>
    <message>
        <source>forced run at period %1</source>
        <comment>tuning.progress.forced_run</comment>
        <translation>周期 %1 的强迫振荡试验</translation>
    </message>
    <message>
        <source>relay run</source>
        <comment>tuning.progress.relay_run</comment>
        <translation>继电试验</translation>
    </message>
    <message>
        <source>%1 — about %2 left</source>
        <comment>tuning.progress.with_eta</comment>
        <translation>%1 — 约剩 %2</translation>
    </message>
    <message>
        <source>verified</source>
        <comment>tuning.progress.verified</comment>
        <translation>已验证</translation>
    </message>
    <message>
        <source>step test done</source>
        <comment>tuning.progress.step_done</comment>
        <translation>阶跃测试完成</translation>
    </message>
    <message>
        <source>done</source>
        <comment>tuning.progress.done</comment>
        <translation>完成</translation>
    </message>
    <message>
        <source>the relay record is too short</source>
        <comment>tuning.relay.record_too_short</comment>
        <translation>继电试验记录太短</translation>
    </message>
    <message>
        <source>the relay did not oscillate (fewer than three cycles)</source>
        <comment>tuning.relay.no_oscillation</comment>
        <translation>继电试验没有产生振荡（不足三个周期）</translation>
    </message>
    <message>
        <source>the relay chattered at the loop rate (it switched every period): raise the hysteresis above the noise on the output</source>
        <comment>tuning.relay.chatter</comment>
        <translation>继电器以控制频率抖动（每个周期都切换）：请把滞环调到高于输出噪声</translation>
    </message>
    <message>
        <source>the relay oscillation did not settle into stable cycles</source>
        <comment>tuning.relay.unsettled</comment>
        <translation>继电振荡没有稳定成等幅周期</translation>
    </message>
    <message>
        <source>the oscillation is no larger than the hysteresis: lower the hysteresis or raise the amplitude</source>
        <comment>tuning.relay.below_hysteresis</comment>
        <translation>振荡幅值不大于滞环：请减小滞环或增大继电幅值</translation>
    </message>
    <message>
        <source>%1 (the run ended: %2)</source>
        <comment>tuning.relay.failed_run_ended</comment>
        <translation>%1（试验结束原因：%2）</translation>
    </message>
    <message>
        <source>a refinement run ended early (%1): the classic relay estimate is reported</source>
        <comment>tuning.relay.refinement_ended</comment>
        <translation>一次细化试验提前结束（%1）：给出经典继电法的估计值</translation>
    </message>
    <message>
        <source>the refinement found no point lagging more than 180° between ω = %1 and %2 rad/s: the phase may never reach −180° (no finite ultimate gain); the classic relay estimate is reported</source>
        <comment>tuning.relay.no_point_lagging_more</comment>
        <translation>在 ω = %1 到 %2 rad/s 之间，细化没有找到相位滞后超过 180° 的点：相位可能永远达不到 −180°（不存在有限的临界增益）；给出经典继电法的估计值</translation>
    </message>
    <message>
        <source>the refinement found no point lagging less than 180° between ω = %1 and %2 rad/s; the classic relay estimate is reported</source>
        <comment>tuning.relay.no_point_lagging_less</comment>
        <translation>在 ω = %1 到 %2 rad/s 之间，细化没有找到相位滞后小于 180° 的点；给出经典继电法的估计值</translation>
    </message>
    <message>
        <source>the refinement reached the loop&apos;s Nyquist limit: the classic relay estimate is reported</source>
        <comment>tuning.relay.nyquist</comment>
        <translation>细化已到达控制回路的奈奎斯特频率：给出经典继电法的估计值</translation>
    </message>
    <message>
        <source>the first trial gain %1 must be above 0 and at most the largest gain %2</source>
        <comment>tuning.ultimate.bad_start_kp</comment>
        <translation>首次试验增益 %1 必须大于 0 且不大于最大增益 %2</translation>
    </message>
    <message>
        <source>trials keep hitting the envelope before a cycle can be measured: widen the envelope or use a smaller step</source>
        <comment>tuning.ultimate.envelope_hits</comment>
        <translation>试验总在测出一个周期之前就超出安全包络：请放宽安全包络或减小阶跃</translation>
    </message>
    <message>
        <source>no Kp with a sustained oscillation after %1 trials (nearest: Kp = %2, cycle ratio %3)</source>
        <comment>tuning.ultimate.no_sustained_nearest</comment>
        <translation>经过 %1 次试验，仍未找到产生等幅振荡的 Kp（最接近的：Kp = %2，周期幅值比 %3）</translation>
    </message>
    <message>
        <source>no sustained oscillation up to Kp = %1: the loop decays at every gain tried, so it may have no finite ultimate gain (its phase may never reach −180°)</source>
        <comment>tuning.ultimate.decays_up_to</comment>
        <translation>直到 Kp = %1 都没有等幅振荡：所有试过的增益下回路都在衰减，因此可能不存在有限的临界增益（相位可能永远达不到 −180°）</translation>
    </message>
    <message>
        <source>the search stalled at Kp = %1</source>
        <comment>tuning.ultimate.stalled</comment>
        <translation>搜索停滞在 Kp = %1</translation>
    </message>
    <message>
        <source>trial %1: Kp = %2</source>
        <comment>tuning.label.trial</comment>
        <translation>试验 %1：Kp = %2</translation>
    </message>
    <message>
        <source>forced run at %1 period</source>
        <comment>tuning.label.forced_run</comment>
        <translation>周期 %1 的强迫振荡试验</translation>
    </message>
    <message>
        <source>relay run</source>
        <comment>tuning.label.relay_run</comment>
        <translation>继电试验</translation>
    </message>
    <message>
        <source>verification with %1 gains</source>
        <comment>tuning.label.verification</comment>
        <translation>用 %1 增益验证</translation>
    </message>
    <message>
        <source>step %1</source>
        <comment>tuning.label.step</comment>
        <translation>阶跃 %1</translation>
    </message>
    <message>
        <source>step test</source>
        <comment>tuning.label.step_test</comment>
        <translation>阶跃测试</translation>
    </message>
    <message>
        <source>the target is not ready (connect the instrument first)</source>
        <comment>tuning.run.target_not_ready</comment>
        <translation>对象未就绪（请先连接仪器）</translation>
    </message>
    <message>
        <source>every envelope limit must be above 0</source>
        <comment>tuning.run.envelope_not_positive</comment>
        <translation>安全包络的各项限值都必须大于 0</translation>
    </message>
    <message>
        <source>the trial step must be above 0 and below %1 of the envelope&apos;s excursion and following-error limits</source>
        <comment>tuning.run.trial_step_invalid</comment>
        <translation>试验阶跃必须大于 0，且小于安全包络中偏移限值和跟随误差限值的 %1</translation>
    </message>
    <message>
        <source>the relay amplitude must be above 0 and the hysteresis not negative</source>
        <comment>tuning.run.relay_invalid</comment>
        <translation>继电幅值必须大于 0，滞环不能为负</translation>
    </message>
    <message>
        <source>a step test cannot start now: another run is in progress</source>
        <comment>tuning.run.step_busy</comment>
        <translation>现在不能开始阶跃测试：另一项试验正在进行</translation>
    </message>
    <message>
        <source>a step test cannot start now: the target is not ready</source>
        <comment>tuning.run.step_not_ready</comment>
        <translation>现在不能开始阶跃测试：对象未就绪</translation>
    </message>
    <message>
        <source>step test not started: %1</source>
        <comment>tuning.run.step_refused</comment>
        <translation>阶跃测试未开始：%1</translation>
    </message>
    <message>
        <source>aborted while interrupted: nothing is running on the device</source>
        <comment>tuning.run.aborted_while_interrupted</comment>
        <translation>在中断状态下中止：设备上没有正在运行的试验</translation>
    </message>
    <message>
        <source>resumed: running the interrupted experiment again</source>
        <comment>tuning.run.resumed</comment>
        <translation>已继续：重新运行被中断的试验</translation>
    </message>
    <message>
        <source>E-stop during %1: the device ended the test and halted the axis; the gains in force are the ones from before (trial gains only ever lived inside the test)</source>
        <comment>tuning.run.estop</comment>
        <translation>%1 期间急停：设备结束了测试并停住该轴；生效的增益仍是原来的（试验增益只在测试中使用）</translation>
    </message>
    <message>
        <source>%1 ended because the device heard nothing from BenchPilot for 0.5 s; the axis holds under its own gains. Resume when the link is steady.</source>
        <comment>tuning.run.host_silent</comment>
        <translation>%1 结束：设备 0.5 s 内未收到 BenchPilot 的消息；该轴以自身增益保持。待连接稳定后按“继续”。</translation>
    </message>
    <message>
        <source>a fault or a switch ended %1; the axis is stopped</source>
        <comment>tuning.run.fault</comment>
        <translation>故障或开关信号结束了 %1；该轴已停止</translation>
    </message>
    <message>
        <source>aborted during %1: the axis is stopped, its gains unchanged</source>
        <comment>tuning.run.aborted_during</comment>
        <translation>在 %1 期间中止：该轴已停止，增益未改变</translation>
    </message>
    <message>
        <source>%1 was stopped (STOP or TEST_ABORT from elsewhere); the axis is stopped, its gains unchanged</source>
        <comment>tuning.run.stopped_elsewhere</comment>
        <translation>%1 被停止（来自其他地方的 STOP 或 TEST_ABORT）；该轴已停止，增益未改变</translation>
    </message>
    <message>
        <source>%1 interrupted: %2. Reconnect, then Resume to run it again.</source>
        <comment>tuning.run.interrupted</comment>
        <translation>%1 被中断：%2。请重新连接，然后按“继续”重新运行。</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <comment>tuning.run.failed</comment>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>Ku = %1, Tu = %2; verification step test with %3 gains: %4</source>
        <comment>tuning.run.verified</comment>
        <translation>Ku = %1，Tu = %2；用 %3 增益的验证阶跃测试：%4</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <comment>tuning.run.step_done</comment>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>aborted after %1: nothing runs on the target; the gains in force are unchanged</source>
        <comment>tuning.run.aborted_after</comment>
        <translation>在 %1 之后中止：对象上没有正在运行的试验；生效的增益未改变</translation>
    </message>
    <message>
        <source>%1 hit the envelope before a cycle could be measured: repeating it with half the step</source>
        <comment>tuning.run.repeat_half_step</comment>
        <translation>%1 在测出一个周期之前就超出了安全包络：以一半阶跃重做</translation>
    </message>
    <message>
        <source>ultimate-gain search: %1</source>
        <comment>tuning.run.ultimate_failed</comment>
        <translation>临界增益搜索：%1</translation>
    </message>
    <message>
        <source>relay autotune: %1</source>
        <comment>tuning.run.relay_failed</comment>
        <translation>继电自整定：%1</translation>
    </message>
    <message>
        <source>Ku = %1, Tu = %2</source>
        <comment>tuning.run.found</comment>
        <translation>Ku = %1，Tu = %2</translation>
    </message>
    <message>
        <source>the link to %1 was lost; the device ends the test by itself within 0.5 s and holds the axis under the gains it had before</source>
        <comment>tuning.target.link_lost</comment>
        <translation>与%1的连接中断；设备会在 0.5 s 内自行结束测试，并以原有增益保持该轴</translation>
    </message>
    <message>
        <source>reading the device&apos;s capture</source>
        <comment>tuning.target.reading_capture</comment>
        <translation>正在读取设备的采集数据</translation>
    </message>
    <message>
        <source>reading the device&apos;s capture: %1 of %2 samples</source>
        <comment>tuning.target.reading_capture_of</comment>
        <translation>正在读取设备的采集数据：%1/%2 个采样点</translation>
    </message>
    <message>
        <source>aborted</source>
        <comment>tuning.target.aborted</comment>
        <translation>已中止</translation>
    </message>
    <message>
        <source>is missing (method is &quot;%1&quot;)</source>
        <comment>tuning.file.missing_for_method</comment>
        <translation>缺失（方法为“%1”）</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a rule BenchPilot knows</source>
        <comment>tuning.file.unknown_rule</comment>
        <translation>“%1”不是 BenchPilot 认识的整定规则</translation>
    </message>
    <message>
        <source>idle</source>
        <comment>tuning.state.idle</comment>
        <translation>空闲</translation>
    </message>
    <message>
        <source>running</source>
        <comment>tuning.state.running</comment>
        <translation>运行中</translation>
    </message>
    <message>
        <source>interrupted</source>
        <comment>tuning.state.interrupted</comment>
        <translation>已中断</translation>
    </message>
    <message>
        <source>done</source>
        <comment>tuning.state.done</comment>
        <translation>已完成</translation>
    </message>
    <message>
        <source>failed</source>
        <comment>tuning.state.failed</comment>
        <translation>失败</translation>
    </message>
    <message>
        <source>aborted</source>
        <comment>tuning.state.aborted</comment>
        <translation>已中止</translation>
    </message>
    <message>
        <source>running</source>
        <comment>tuning.end.running</comment>
        <translation>运行中</translation>
    </message>
    <message>
        <source>settled</source>
        <comment>tuning.end.settled</comment>
        <translation>已稳定</translation>
    </message>
    <message>
        <source>completed</source>
        <comment>tuning.end.completed</comment>
        <translation>已完成</translation>
    </message>
    <message>
        <source>max excursion crossed</source>
        <comment>tuning.end.excursion</comment>
        <translation>超出最大偏移</translation>
    </message>
    <message>
        <source>max following error crossed</source>
        <comment>tuning.end.following_error</comment>
        <translation>超出最大跟随误差</translation>
    </message>
    <message>
        <source>max duration reached</source>
        <comment>tuning.end.duration</comment>
        <translation>达到最长时间</translation>
    </message>
    <message>
        <source>stopped</source>
        <comment>tuning.end.stopped</comment>
        <translation>已停止</translation>
    </message>
    <message>
        <source>E-stop</source>
        <comment>tuning.end.estop</comment>
        <translation>急停</translation>
    </message>
    <message>
        <source>host went silent</source>
        <comment>tuning.end.host_silent</comment>
        <translation>上位机无响应</translation>
    </message>
    <message>
        <source>fault</source>
        <comment>tuning.end.fault</comment>
        <translation>故障</translation>
    </message>
    <message>
        <source>unknown</source>
        <comment>tuning.end.unknown</comment>
        <translation>未知</translation>
    </message>
    <message>
        <source>decays</source>
        <comment>tuning.outcome.decays</comment>
        <translation>衰减</translation>
    </message>
    <message>
        <source>sustained</source>
        <comment>tuning.outcome.sustained</comment>
        <translation>等幅</translation>
    </message>
    <message>
        <source>grows</source>
        <comment>tuning.outcome.grows</comment>
        <translation>发散</translation>
    </message>
    <message>
        <source>no oscillation</source>
        <comment>tuning.outcome.no_oscillation</comment>
        <translation>未振荡</translation>
    </message>
    <message>
        <source>hit the envelope</source>
        <comment>tuning.outcome.hit_envelope</comment>
        <translation>超出安全包络</translation>
    </message>
    <message>
        <source>Ziegler–Nichols P</source>
        <comment>tuning.rule.zn-p</comment>
        <translation>Ziegler–Nichols P</translation>
    </message>
    <message>
        <source>Ziegler–Nichols PI</source>
        <comment>tuning.rule.zn-pi</comment>
        <translation>Ziegler–Nichols PI</translation>
    </message>
    <message>
        <source>Ziegler–Nichols PID</source>
        <comment>tuning.rule.zn-pid</comment>
        <translation>Ziegler–Nichols PID</translation>
    </message>
    <message>
        <source>Tyreus–Luyben PI</source>
        <comment>tuning.rule.tl-pi</comment>
        <translation>Tyreus–Luyben PI</translation>
    </message>
    <message>
        <source>Tyreus–Luyben PID</source>
        <comment>tuning.rule.tl-pid</comment>
        <translation>Tyreus–Luyben PID</translation>
    </message>
    <message>
        <source>Pessen integral rule PID</source>
        <comment>tuning.rule.pessen</comment>
        <translation>Pessen 积分法则 PID</translation>
    </message>
    <message>
        <source>Z-N &quot;some overshoot&quot; PID</source>
        <comment>tuning.rule.some-overshoot</comment>
        <translation>Z-N“少量超调” PID</translation>
    </message>
    <message>
        <source>Z-N &quot;no overshoot&quot; PID</source>
        <comment>tuning.rule.no-overshoot</comment>
        <translation>Z-N“无超调” PID</translation>
    </message>
    <message numerus="yes">
        <source>no Kp with a sustained oscillation after %Ln trials</source>
        <comment>tuning.ultimate.no_sustained</comment>
        <translation>
            <numerusform>经过 %Ln 次试验，仍未找到产生等幅振荡的 Kp</numerusform>
        </translation>
    </message>
</context>
</TS>
